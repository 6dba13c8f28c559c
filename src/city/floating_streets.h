// The streets of a futuristic city's upper levels (Goitowski 2010, L3075–3117 and L3946–3951,
// digest-002 §4): thick slabs floating in the air, joined at the crossings by solids made from
// the street directions, and the lift platforms that join the levels. Every piece is a closed
// solid, so that the path tracer sees no gap under a floating street.
#pragma once

#include <span>
#include <vector>

#include "core/vecmath.h"
#include "scene/mesh.h"

namespace veduta {

// A street meeting a crossing: its direction away from the centre (x/y) and its width.
struct CrossingArm {
    Vec2f direction;
    float width = 7;
};

// A crossing (L3075–3117): per arm two contour points, half the arm's width either side of it,
// `mouth` metres out from the centre; the centre and those 2n points triangulated (Delaunay, so
// that arms at a tiny angle still give valid triangles: points inside the hull are kept, not
// lost; points within a millimetre of one another are one), the top at centre.z facing up, and the whole extruded
// `thickness` down into a closed solid. Texture coordinates: planar x/y, metres.
Mesh crossingSolid(const Vec3f &centre, std::span<const CrossingArm> arms, float mouth, float thickness);

// A closed box spanned from `corner` by three edges (either handedness; the faces face out), its
// faces with texture coordinates in metres along their first two edges. A street slab, a lift's
// platform or a rail.
Mesh solidBox(const Vec3f &corner, const Vec3f &e1, const Vec3f &e2, const Vec3f &e3);

// A street's slab from a to b (the middle of its top at both ends), `width` wide, `thickness`
// deep: its top slopes where a and b lie at different heights.
Mesh streetSlab(const Vec3f &a, const Vec3f &b, float width, float thickness);

}  // namespace veduta
