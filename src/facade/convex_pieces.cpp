#include "facade/convex_pieces.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_triangulation_decomposition_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/partition_2.h>

#include <algorithm>
#include <iterator>
#include <list>

namespace veduta {
namespace {

// Exact predicates on the doubles as they are: the partition and its checks decide with them.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;

// The ring without repeated or collinear vertices, a spike folding back on itself included (exact
// orientation tests); fewer than three points when nothing with area is left.
std::vector<Point> cleaned(const std::vector<Vec2d> &ring) {
    std::vector<Point> points;
    for (Vec2d p : ring) points.emplace_back(p.x, p.y);
    bool changed = true;
    while (changed && points.size() >= 3) {
        changed = false;
        for (size_t i = 0; i < points.size() && points.size() >= 3;) {
            const Point &before = points[(i + points.size() - 1) % points.size()];
            const Point &after = points[(i + 1) % points.size()];
            if (CGAL::orientation(before, points[i], after) == CGAL::COLLINEAR) {
                points.erase(points.begin() + std::ptrdiff_t(i));
                changed = true;
            } else {
                ++i;
            }
        }
    }
    return points;
}

template <typename Points>
std::vector<Vec2d> doubles(const Points &points) {
    std::vector<Vec2d> result;
    for (const Point &p : points) result.push_back({p.x(), p.y()});
    return result;
}

}  // namespace

std::vector<std::vector<Vec2d>> convexPieces(const std::vector<Vec2d> &outline,
                                             const std::vector<std::vector<Vec2d>> &holes) {
    std::vector<Point> points = cleaned(outline);
    if (points.size() < 3) return {};
    std::vector<std::vector<Point>> holeRings;
    for (const auto &hole : holes) {
        std::vector<Point> ring = cleaned(hole);
        if (ring.size() >= 3) holeRings.push_back(std::move(ring));
    }
    std::vector<std::vector<Vec2d>> pieces;
    if (holeRings.empty() && CGAL::is_simple_2(points.begin(), points.end(), Kernel())) {
        if (CGAL::orientation_2(points.begin(), points.end(), Kernel()) == CGAL::CLOCKWISE)
            std::reverse(points.begin(), points.end());
        if (CGAL::is_convex_2(points.begin(), points.end(), Kernel())) return {doubles(points)};
        std::list<CGAL::Partition_traits_2<Kernel>::Polygon_2> convex;
        CGAL::optimal_convex_partition_2(points.begin(), points.end(), std::back_inserter(convex));
        for (const auto &part : convex) pieces.push_back(doubles(part.container()));
        return pieces;
    }
    // Holes, or a ring that touches or crosses itself: the constrained triangulation takes every
    // edge as it comes and keeps the triangles inside by the parity of the rings around them.
    CGAL::Polygon_with_holes_2<Kernel> region(Polygon(points.begin(), points.end()));
    for (const auto &ring : holeRings) region.add_hole(Polygon(ring.begin(), ring.end()));
    std::list<Polygon> triangles;
    CGAL::Polygon_triangulation_decomposition_2<Kernel>()(region, std::back_inserter(triangles));
    for (const Polygon &triangle : triangles) {
        // A triangle flattened by a rounded crossing point is no piece.
        if (CGAL::orientation(triangle[0], triangle[1], triangle[2]) == CGAL::LEFT_TURN)
            pieces.push_back(doubles(triangle.vertices()));
    }
    return pieces;
}

}  // namespace veduta
