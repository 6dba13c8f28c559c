// A face of a plan lifted out as the next level's outline (digest-003 §2.2, L1602–1606): its
// corners counter-clockwise and what lies beyond each of its edges. Edge i runs from points[i]
// to points[i + 1 mod n]. A lot is such a shape cut from its block, a building's footprint one
// cut from its lot, an apartment one cut from its storey.
#pragma once

#include <vector>

#include "slg/edge_location.h"
#include "slg/plan_geometry.h"

namespace veduta {

struct PlanShape {
    Polygon2d points;
    std::vector<EdgeLocation> locations;

    size_t size() const { return points.size(); }
    Vec2d start(size_t edge) const { return points[edge]; }
    Vec2d end(size_t edge) const { return points[(edge + 1) % points.size()]; }
    double edgeLength(size_t edge) const { return length(end(edge) - start(edge)); }
};

}  // namespace veduta
