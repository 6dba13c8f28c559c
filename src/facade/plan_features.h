// The features (Merkmale) of a floor plan (Def 4.6, L735-847; digest-001 §2.1): the outline cut
// into the polylines that each module contributes between two connections, each piece tagged
// with its element and parameter range (e5[b,1] is {module, edge 4}, t0 = b, t1 = 1).
//
// The outline is the one FloorPlan walks (counter-clockwise, see floor_plan.h); a feature is a
// maximal run of it that belongs to one module, which covers the thesis's nine cases:
// * cases 1-6 and 9: the run of module edges between two transitions (case 1: the whole
//   polygon, starting at e1; case 6: c1[b1, a2] between two docks on one edge);
// * case 7: the pieces g[0, a2] and g[b2, 1] of a PP edge g belong to the module docked on g;
//   a piece of g between two docked modules is a feature of its own, as case 6 is (the thesis
//   shows only one docked module, so this is our reading);
// * case 8: a bare PP edge is a feature of its own, owned by no module.
// Inner PP edges (Fig. 4.15) are not on the outline and so in no feature.
#pragma once

#include <vector>

#include "core/vecmath.h"
#include "facade/floor_plan.h"

namespace veduta {

struct Feature {
    int module = -1;        // the module it belongs to; -1 for a bare PP edge (case 8)
    int ppConnection = -1;  // the PP connection of a bare PP edge, else -1
    std::vector<WalkPiece> edges;
};

// The features in outline order, starting at a transition between two features.
std::vector<Feature> planFeatures(const FloorPlan &plan);

// The outline's vertices, counter-clockwise, from the features' edges (points where a feature
// edge passes a connection stay in, as collinear vertices).
std::vector<Vec2d> featureOutline(const std::vector<Feature> &features);

}  // namespace veduta
