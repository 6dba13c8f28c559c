// Gable and half-hip ("Krüppelwalm") ends on a hip roof (issue 7, docs/roofs.md). CGAL 5.5's
// straight skeleton has no weights, so a gable is made from the hip: the triangular hip face
// at the end of a ridge becomes a vertical wall over its edge, its apex moved along the ridge
// (where the two neighbouring slopes meet) onto the edge's line, so that those slopes stretch
// to the gable and stay planar. On a rectangle that is the edge's midpoint at ridge height.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "city/roof_skeleton.h"

namespace veduta {

// An edge still ends a ridge when its face is a triangle under a skeleton corner that no
// earlier gable has moved or taken.
bool endsARidge(const SkeletonRoof &roof, size_t edge);

// The edges that end a ridge, shortest first (ties: the lower index): a rectangle's short sides.
std::vector<size_t> ridgeEnds(const SkeletonRoof &roof);

// Within these the edited faces must stay planar (metres).
inline constexpr double kMaxPlaneDistance = 1e-4;
// A gable's apex keeps this far from its edge's ends, and rises at least this high (metres).
inline constexpr double kMinGableSize = 0.01;

// Turns the hip at `edge` (which must end a ridge) into a gable wall (RoofGableWall) up to the
// ridge. With a halfHipFraction in (0, 1) the wall stops at that fraction of the gable's height
// and a small hip rises from its top at the roof's pitch to the ridge. Returns why it cannot,
// leaving the roof as it was, when the ridge meets the edge's line off the edge, the gable
// would be lower than kMinGableSize, or an edited face would cross itself or leave its plane.
std::optional<std::string> addGableEnd(SkeletonRoof &roof, size_t edge, std::optional<float> halfHipFraction);

}  // namespace veduta
