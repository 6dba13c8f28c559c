// Bilke's mansard roof (CreateRoof, Bilke 2009, §2.4.3: a flat-topped mansard over every house
// but the rectangular ones on one street, which get a gable; roof_shapes.h builds that gable and
// every other roof type, roof_choice.h makes the thesis' choice).
#pragma once

#include <vector>

#include "city/footprint.h"
#include "scene/mesh.h"

namespace veduta {

inline constexpr float kRightAngleToleranceDegrees = 1;
// Whether every corner of the footprint is a right angle within kRightAngleToleranceDegrees.
bool isRightAngled(const Footprint &footprint);

// Roof meshes are in world coordinates, with flat per-face normals pointing out and up, UVs
// in metres, and triangleMaterials holding RoofSurface values. Heights are above the
// footprint's base.
enum RoofSurface : MaterialId { RoofCovering = 0, RoofGableWall = 1 };

struct MansardRoof {
    Mesh mesh;
    float inset = 0;         // the inset used, after halving
    std::vector<Vec2f> top;  // the flat top's outline, one point per footprint point
};

// The footprint inset by `inset` (each edge moved inwards) and raised by roofHeight as a
// flat top, joined to the eaves by one sloping quad per edge. An inset the footprint cannot
// take is halved until it can, at most kMansardInsetHalvings times; after that, or with no
// inset, the roof is the footprint, flat at the eaves, with inset 0 and no slopes.
inline constexpr int kMansardInsetHalvings = 8;
MansardRoof mansardRoof(const Footprint &footprint, float eavesHeight, float roofHeight, float inset);

}  // namespace veduta
