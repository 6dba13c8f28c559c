// Polygon helpers the masonry shares (ashlar, cyclopean, the wall mask, Lloyd relaxation): the
// convex pieces a cut stone is split into (Fig. 5.11), core's signed area, and the conversions
// between rings of doubles and CGAL's exact polygons, in one place.
#pragma once

#include <vector>

#include "core/polygon_area.h"
#include "core/vecmath.h"

namespace veduta {

// The ring as a CGAL polygon (`Polygon` of any kernel), vertex for vertex. A template, so that
// this header stays free of CGAL for the files that need only the rest.
template <typename Polygon>
Polygon cgalPolygon(const std::vector<Vec2d> &ring) {
    Polygon polygon;
    for (Vec2d p : ring) polygon.push_back({p.x, p.y});
    return polygon;
}

// A polygon of an exact kernel rounded to double, without the repeated points rounding leaves
// between neighbours (also across the ring's end).
template <typename Polygon>
std::vector<Vec2d> roundedRing(const Polygon &polygon) {
    std::vector<Vec2d> ring;
    for (const auto &p : polygon.vertices()) {
        Vec2d q{to_double(p.x()), to_double(p.y())};  // CGAL's, found by argument-dependent lookup
        if (ring.empty() || !(q == ring.back())) ring.push_back(q);
    }
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    return ring;
}

// The region bounded by `outline` (counter-clockwise) less its `holes` as convex, counter-clockwise
// pieces: the outline itself when it is convex and has no hole, CGAL's fewest convex pieces when
// it is simple, an axis-parallel rectangle around one convex hole strictly inside it as the bands
// around the hole's box and triangles fanned from the box's corners to the hole's edges (a wall
// element around its opening), else triangles. Repeated and collinear vertices are dropped first (exact tests).
// Rings cut exactly and rounded to double may touch themselves at a vertex (two grown openings
// meeting at a corner, an opening touching the wall's edge) or, by rounding, cross; the optimal
// partition must not see those (a CGAL precondition), the triangulation takes them. Empty when
// nothing with area is left.
std::vector<std::vector<Vec2d>> convexPieces(const std::vector<Vec2d> &outline,
                                             const std::vector<std::vector<Vec2d>> &holes = {});

}  // namespace veduta
