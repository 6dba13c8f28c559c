// The building of Goitowski's futuristic cities (Goitowski 2010, L3052–3073 and L3916–3937,
// digest-002 §4 and §6): one prism over a lot, its flat roof a constrained Delaunay
// triangulation of the footprint, floating ones closed below by the same triangulation turned
// over, its walls quads textured with a tiling facade whose repeats are whole numbers, so that
// no window is cut at a corner.
#pragma once

#include <span>

#include "core/vecmath.h"
#include "scene/mesh.h"

namespace veduta {

// The thesis's heights: U[7, 18] metres, one storey and a roof.
inline constexpr float kPrismMinHeight = 7, kPrismMaxHeight = 18;

// How often a texture of `tile` units fits along `length`: rounded to the nearest whole number,
// at least once (L3916–3922): 10.4 m of wall with a 3 m tile take it 3 times, 1 m once.
int uvRepeats(float length, float tile);

// Surfaces the prism's triangleMaterials hold.
enum PrismSurface : MaterialId { PrismWall = 0, PrismRoof = 1, PrismFloor = 2 };

// A closed prism over `outline` (simple, counter-clockwise, x/y) from `base` to base + height:
// the walls face out, each a quad with texture coordinates running 0 … repeats × tile in both
// directions (a material of texture size `tile` shows each wall a whole number of tiles); the
// roof faces up and the floor down, both with planar x/y texture coordinates in metres. The
// floor is there for every prism: a prism standing on the ground hides it, a floating one
// needs it, and either way the solid is closed (watertight) for the path tracer.
Mesh prismBuilding(std::span<const Vec2f> outline, float base, float height, Vec2f tile);

}  // namespace veduta
