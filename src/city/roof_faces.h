// The planar faces roof builders emit (roofs.h, roof_shapes.h): flat normals, UVs in metres,
// RoofSurface materials.
#pragma once

#include <vector>

#include "city/roofs.h"

namespace veduta {

// Texture coordinates in metres on a plane: distances from `origin` along two unit axes.
struct UvPlane {
    Vec3f origin, u, v;
    Vec2f at(const Vec3f &p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
};

// The unit normal of a planar polygon, counter-clockwise seen from its front: Newell's sum,
// taken relative to the first corner so that buildings far from the origin keep their precision.
Vec3f faceNormal(const std::vector<Vec3f> &corners);

// A roof covering's texture runs one tile per metre along its eaves (from corners[0] to
// corners[1]) and one per metre up the slant, not per metre of height, so that tiles keep
// their size on any pitch.
UvPlane slopeUvPlane(const std::vector<Vec3f> &corners);

// A wall's texture as the facades' runs (building_generator.h): u in metres along the outline
// from its start, `perimeterBefore` metres before the edge from `start` in direction `along`,
// and v the height above `base`.
UvPlane wallUvPlane(Vec2f start, const Vec3f &along, float perimeterBefore, float base);

// A convex face, counter-clockwise seen from outside, with its own vertices, so that its normal
// is the face's.
void addFace(Mesh &m, const std::vector<Vec3f> &corners, const UvPlane &uv, RoofSurface surface);

// A planar face that is not vertical, of any simple outline counter-clockwise seen from above
// (rings[0]) with clockwise holes (the rest): triangulated in its projection onto the ground,
// with the given normal at every corner.
void addProjectedFace(Mesh &m, const std::vector<std::vector<Vec3f>> &rings, const Vec3f &normal, const UvPlane &uv,
                      RoofSurface surface);

}  // namespace veduta
