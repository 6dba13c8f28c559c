// The painted lines of roads (geo/road_style.h) on their draped ribbons (geo/ribbons.h):
// centre, lane and edge lines, dashed or solid, cut back where a road ends at another, and a
// stop line where it meets one of the same or a higher rank. Every mark lies `lift` above the
// ribbon's own triangles, with vertices where the ribbon's diagonals cross it, so it follows
// the ribbon's surface exactly. docs/roads.md.
#pragma once

#include <span>

#include "geo/road_style.h"
#include "scene/mesh.h"

namespace veduta {

struct MarkedRoad {
    RoadStyle style;
    const Mesh *ribbon = nullptr;  // drapeRibbon's mesh of one of its lines
};

struct MarkingOptions {
    double lift = 0.01;              // metres above the ribbon
    double junctionTolerance = 0.5;  // metres: an end this near another line meets it
    double stopLineSetback = 1.0;    // metres from the crossing carriageway's edge to the stop line
};

// The marks of all roads, in one up-facing mesh (material 0). Roads meet where an end of one
// lies within junctionTolerance of another's centre line: a road that goes on in one other
// road (a line cut in two) is painted through; otherwise its lines stop short of the other
// carriageway, and where it ends on another road's side or at a node with a higher-ranked road
// it gets a stop line across its approach lane (when its style has one), and the road it
// ends on has its edge line opened there.
Mesh roadMarkings(std::span<const MarkedRoad> roads, const MarkingOptions &options);

}  // namespace veduta
