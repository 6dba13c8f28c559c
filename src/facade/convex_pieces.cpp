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
#include <optional>

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

// A wall element's common case, without a triangulation: `outer` an axis-parallel rectangle
// around one convex `hole` (both cleaned) that lies strictly inside it. The pieces are the bands
// left and right of the hole's box and below and above it, and in the box, for each hole edge, the
// triangle to the box corner its outside faces: the edges facing one corner run monotonically
// round it, so their fan fills what lies between them and the corner. All corners are the input
// points: nothing is rounded. Nothing when the case does not apply.
std::optional<std::vector<std::vector<Vec2d>>> framePieces(const std::vector<Point> &outer, std::vector<Point> hole) {
    if (outer.size() != 4) return std::nullopt;
    for (size_t i = 0; i < 4; ++i) {
        const Point &a = outer[i], &b = outer[(i + 1) % 4];
        if ((a.x() == b.x()) == (a.y() == b.y())) return std::nullopt;  // an edge not axis-parallel
    }
    CGAL::Bbox_2 frame = CGAL::bbox_2(outer.begin(), outer.end());
    if (!CGAL::is_convex_2(hole.begin(), hole.end(), Kernel())) return std::nullopt;
    if (CGAL::orientation_2(hole.begin(), hole.end(), Kernel()) == CGAL::CLOCKWISE)
        std::reverse(hole.begin(), hole.end());
    CGAL::Bbox_2 box = CGAL::bbox_2(hole.begin(), hole.end());
    if (!(frame.xmin() < box.xmin() && box.xmax() < frame.xmax() && frame.ymin() < box.ymin() &&
          box.ymax() < frame.ymax()))
        return std::nullopt;
    auto rectangle = [](double x0, double y0, double x1, double y1) {
        return std::vector<Vec2d>{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    };
    std::vector<std::vector<Vec2d>> pieces{rectangle(frame.xmin(), frame.ymin(), box.xmin(), frame.ymax()),
                                           rectangle(box.xmax(), frame.ymin(), frame.xmax(), frame.ymax()),
                                           rectangle(box.xmin(), frame.ymin(), box.xmax(), box.ymin()),
                                           rectangle(box.xmin(), box.ymax(), box.xmax(), frame.ymax())};
    for (size_t i = 0; i < hole.size(); ++i) {
        const Point &a = hole[i], &b = hole[(i + 1) % hole.size()];
        // The edge's outside lies to its right: (dy, −dx).
        double outX = b.y() - a.y(), outY = a.x() - b.x();
        Point corner(outX >= 0 ? box.xmax() : box.xmin(), outY >= 0 ? box.ymax() : box.ymin());
        if (CGAL::orientation(corner, b, a) == CGAL::LEFT_TURN) pieces.push_back(doubles(std::vector{corner, b, a}));
    }
    return pieces;
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
    if (holeRings.size() == 1) {
        if (auto framed = framePieces(points, holeRings[0])) return *framed;
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
