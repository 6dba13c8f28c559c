// Plans as CGAL's exact polygon sets, for the Boolean operations the plans need (corridors,
// quarters): exact where the plans' doubles would leave a Boolean undecided.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "slg/plan_geometry.h"

namespace veduta {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactRegion = CGAL::Polygon_set_2<ExactKernel>;

inline ExactRegion::Polygon_2 exactPolygon(const Polygon2d &points) {
    ExactRegion::Polygon_2 polygon;
    for (Vec2d p : points) polygon.push_back({p.x, p.y});
    return polygon;
}

inline Polygon2d inexactPolygon(const ExactRegion::Polygon_2 &polygon) {
    Polygon2d points;
    for (const auto &p : polygon.vertices()) points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
    return points;
}

}  // namespace veduta
