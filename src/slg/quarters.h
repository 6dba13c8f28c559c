// A district too large to plan in one piece cut into quarters by main streets. Schrader's
// levels cut a city into districts; a district given whole (a whole town's outline) is filled
// ring by ring, and each ring's inner network grows with the square of the district's side
// (its rays cross each other), so the rings together grow with its cube. Quarters of about a
// kilometre keep every ring's network small and the whole linear in the area (docs/slg.md).
#pragma once

#include <vector>

#include "slg/plan_geometry.h"

namespace veduta {

// The outline cut along a square grid of `side` metres turned to its longest edge, each
// piece moved back `street` / 2 from the grid lines: the pieces in row order, each simple and
// counter-clockwise; the whole outline when it fits in one cell.
std::vector<Polygon2d> quarters(const Polygon2d &outline, double side, double street);

}  // namespace veduta
