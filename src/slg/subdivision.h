// One level of Schrader's subdivision (digest-003 §2.2 steps 1–6 and §2.6's reconstruction of
// the part the extraction lost): landmarks on the outline, a ray from each perpendicular into
// it, the rays' crossings as the inner network, then for each pair of neighbouring landmarks the
// closed paths through that network (Listing 2, with its four prunings) and the one that best
// makes a face (two hard and two soft criteria). What no face takes is left as inner faces.
#pragma once

#include <cstdint>
#include <vector>

#include "slg/plan_parameters.h"
#include "slg/plan_random.h"
#include "slg/plan_shape.h"
#include "slg/slg_graph.h"

namespace veduta {

struct PlanFace {
    SlgPath path;  // counter-clockwise
    // A border face's two landmarks: its front runs along the outline from `left` to `right`.
    // An inner face, and the whole outline when it is not subdivided, has neither.
    SlgNodeId left = kNoSlgId, right = kNoSlgId;
    bool isBorder() const { return left != kNoSlgId; }
};

// How far the search goes, and the angles of eq 9 the thesis gives only as ranges (1°–10°,
// 170°–179°). A turn of a path through the network must lie strictly between the two; a path
// that goes straight on through a crossing is one straight run (§2.6, option ii).
struct SearchLimits {
    double minimumTurn = 5, maximumTurn = 175;  // degrees
    int maximumPaths = 4096;                    // candidate paths per face (the thesis saw > 100)
    int maximumSteps = 200000;                  // steps of one face's search
};

struct Subdivision {
    Polygon2d outline;
    SlgGraph graph;
    std::vector<SlgNodeId> landmarks;  // counter-clockwise round the outline
    std::vector<PlanFace> faces;       // the border faces in outline order, then the inner faces
    int deletedFaces = 0;              // landmark pairs no path could make a face of (L1313)
    int keptLeftovers = 0;             // of those, pairs whose leftover face was kept as theirs
    int truncatedSearches = 0;         // faces whose search stopped at SearchLimits
    std::vector<const PlanFace *> borderFaces() const;
};

// Subdivides a simple counter-clockwise outline whose edges have the given locations (the
// parent's). Inner edges start as gaps; the level's rules relabel them (§2.2 step 7).
Subdivision subdivide(const Polygon2d &outline, const std::vector<EdgeLocation> &locations,
                      const PlanParameters &parameters, const PlanRandom &random, const SearchLimits &limits = {});

// A face lifted out as the next level's outline, with its edges' locations (L1602–1606). A
// border face's front is then its first frontEdges(face) edges.
PlanShape faceShape(const Subdivision &subdivision, const PlanFace &face);
size_t frontEdges(const PlanFace &face);

// The faces of a subdivision as polygons, in its order.
std::vector<Polygon2d> facePolygons(const Subdivision &subdivision);

// The lengths of the straight runs round a closed polygon: consecutive collinear edges are one.
std::vector<double> straightRuns(const Polygon2d &polygon);

}  // namespace veduta
