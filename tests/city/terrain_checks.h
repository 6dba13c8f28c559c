// Checks of what a city puts on a landscape's terrain, shared by the street and the city tests.
#pragma once

#include <cstddef>
#include <map>

#include "geo/terrain_surface.h"
#include "scene/mesh.h"
#include "scene/render_scene.h"

namespace veduta::test {

// The point of triangle t at barycentric (a, b), in double from its float vertices.
Vec3d pointIn(const Mesh &mesh, size_t t, double a, double b);

// Points of `mesh` (every vertex and 30 inside each triangle, read in double from its float
// vertices) below the terrain surface where it has one: no tolerance.
size_t pointsBelow(const Mesh &mesh, const TerrainSurface &surface);

// The lowest point of each building's walls (above its plinth) and of its plinth, by building id.
struct Seat {
    float walls = 1e9f, plinth = 1e9f;
};
std::map<uint32_t, Seat> seats(const RenderScene &scene);

MaterialId materialNamed(const RenderScene &scene, const std::string &name);

}  // namespace veduta::test
