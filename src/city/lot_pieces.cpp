#include "city/lot_pieces.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>

namespace veduta::lots {

namespace {

using Point = ExactKernel::Point_2;
using Vector = ExactKernel::Vector_2;

// How far a piece's point may lie from a block edge and still count as on it: float rounding of
// the exact cut points, far below any lot's size.
constexpr double kOnEdge = 1e-3;

// The half-plane left of the line through `on` along `along`, as a quadrilateral of side
// 2 · `reach` (the piece must lie well within reach of `on`).
ExactPolygon halfPlane(Point on, Vector along, double reach) {
    Vector left = along.perpendicular(CGAL::COUNTERCLOCKWISE);
    std::vector<Point> corners{on - along * reach, on + along * reach, on + along * reach + left * reach,
                               on - along * reach + left * reach};
    return ExactPolygon(corners.begin(), corners.end());
}

std::vector<Piece> partsWithin(const ExactPolygon &polygon, const ExactPolygon &region) {
    std::vector<CGAL::Polygon_with_holes_2<ExactKernel>> parts;
    CGAL::intersection(polygon, region, std::back_inserter(parts));
    std::vector<Piece> pieces;
    for (const auto &part : parts) {
        Piece points = toPiece(part.outer_boundary());
        if (points.size() >= 3) pieces.push_back(std::move(points));
    }
    return pieces;
}

}  // namespace

ExactPolygon toExact(const Piece &piece) {
    ExactPolygon polygon;
    for (Vec2f p : piece) polygon.push_back(Point(p.x, p.y));
    return polygon;
}

Piece toPiece(const ExactPolygon &polygon) {
    Piece points;
    for (const Point &p : polygon.vertices()) {
        Vec2f q{float(CGAL::to_double(p.x())), float(CGAL::to_double(p.y()))};
        if (points.empty() || q.x != points.back().x || q.y != points.back().y) points.push_back(q);
    }
    while (points.size() > 1 && points.front().x == points.back().x && points.front().y == points.back().y) {
        points.pop_back();
    }
    return points;
}

std::vector<bool> streetFlags(const Piece &piece, const Block &block) {
    size_t n = piece.size(), m = block.points.size();
    std::vector<bool> flags(n, false);
    for (size_t i = 0; i < n; ++i) {
        for (size_t e = 0; e < m && !flags[i]; ++e) {
            if (!block.streetEdges[e]) continue;
            Vec2f a = block.points[e], b = block.points[(e + 1) % m];
            flags[i] =
                distanceToSegment(piece[i], a, b) < kOnEdge && distanceToSegment(piece[(i + 1) % n], a, b) < kOnEdge;
        }
    }
    return flags;
}

bool hasStreetEdge(const Piece &piece, const Block &block) {
    std::vector<bool> flags = streetFlags(piece, block);
    return std::find(flags.begin(), flags.end(), true) != flags.end();
}

CutSides cutPiece(const Piece &piece, const CutLine &line) {
    ExactPolygon polygon = toExact(piece);
    // Every point of the piece lies within its box's width plus height of any point in the box,
    // and `on` may lie outside the box (an OBB's middle).
    CGAL::Bbox_2 box = polygon.bbox();
    double outside = std::max({0.0, box.xmin() - line.on.x, line.on.x - box.xmax()}) +
        std::max({0.0, box.ymin() - line.on.y, line.on.y - box.ymax()});
    double reach = 2 * (box.xmax() - box.xmin() + box.ymax() - box.ymin() + outside);
    Point on(line.on.x, line.on.y);
    Vector along(line.dx, line.dy);
    return {partsWithin(polygon, halfPlane(on, along, reach)), partsWithin(polygon, halfPlane(on, -along, reach))};
}

}  // namespace veduta::lots
