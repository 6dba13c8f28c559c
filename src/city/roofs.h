// Seed 000's roofs (CreateRoof, thesis L1320–1355, digest-000 §4): a gable roof over a
// rectangular house on one street, a flat-topped mansard roof over everything else. Further
// roof kinds join RoofKind and get their own builders.
#pragma once

#include <vector>

#include "city/footprint.h"
#include "scene/mesh.h"

namespace veduta {

enum class RoofKind { Gable, Mansard };

// Seed 000's choice: a gable when the footprint has four vertices, exactly one street edge and
// right angles (within kRightAngleToleranceDegrees); a mansard otherwise.
inline constexpr float kRightAngleToleranceDegrees = 1;
RoofKind chooseRoofKind(const Footprint &footprint);
// Whether every corner of the footprint is a right angle within kRightAngleToleranceDegrees.
bool isRightAngled(const Footprint &footprint);

// Roof meshes are in world coordinates, with flat per-face normals pointing out and up, UVs
// in metres, and triangleMaterials holding RoofSurface values. Heights are above the
// footprint's base.
enum RoofSurface : MaterialId { RoofCovering = 0, RoofGableWall = 1 };

// A ridge parallel to the first street edge (edge 0 when none faces a street), through the
// midpoints of the two edges next to it, roofHeight above the eaves: two slopes (RoofCovering)
// and two gable ends (RoofGableWall, walls whose UVs continue their facade's). Needs a
// footprint of four points.
Mesh gableRoof(const Footprint &footprint, float eavesHeight, float roofHeight);

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
