// Where a plan's faces meet the outline (digest-003 §2.2 step 2, thesis L1190–1228): the
// landmarks, spread over the outline's edges by length, jittered along them and pulled to a
// fixed distance from concave corners, each with its ray into the outline.
#pragma once

#include <vector>

#include "slg/plan_parameters.h"
#include "slg/plan_random.h"
#include "slg/slg_graph.h"

namespace veduta {

// Eq 5, the counting pass: `count` times, the edge whose length over its landmarks so far plus
// one is largest takes one more (the first such edge on a tie). An edge with k landmarks is cut
// into k + 1 equal parts, so two on one edge give thirds (L1204).
std::vector<int> landmarksPerEdge(const std::vector<double> &edgeLengths, int count);

// The positions along an edge of length `length` (as fractions) of its `k` landmarks: i/(k+1)
// (eq 6), moved by up to ±jitter of their spacing (eq 16), and the ones next to a concave
// corner at its ends moved to `pull` from it (eq 7) where that keeps them in order.
std::vector<double> landmarkPositions(int k, double length, double jitter, bool reflexStart, bool reflexEnd,
                                      double pull, const PlanRandom &random, uint32_t edgeIndex);

// Splits the outer edges of an outline graph (fresh from outlineGraph) at the landmarks and
// returns them in counter-clockwise order round the outline. Fewer than two landmarks leave the
// graph alone and return none: the outline is then the only face (L1228).
std::vector<SlgNodeId> placeLandmarks(SlgGraph &graph, const PlanParameters &parameters, const PlanRandom &random);

}  // namespace veduta
