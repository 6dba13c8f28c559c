// seed 000's subdivideLot-Mueller (thesis L362–374, after Müller 2001): recursive splits of a
// block until every piece is at most MaxLotArea.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "city/lot_subdivision.h"
#include "core/hash.h"

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

// How far a piece's point may lie from a block edge and still count as on it: float rounding of
// the exact cut points, far below any lot's size.
constexpr double kOnEdge = 1e-3;
// An angle within this of 90° counts as right when choosing the edge to split.
constexpr double kRightAngleCosine = 0.0872;  // cos 85°
// Where the cut crosses the chosen edge, as a fraction of its length: normally distributed
// around the middle (the thesis gives no σ).
constexpr float kCutFrom = 0.3f, kCutTo = 0.7f;

// One flag per edge of `piece`: whether the edge lies along a street edge of the block.
std::vector<bool> streetFlags(const std::vector<Vec2f> &piece, const Block &block) {
    size_t n = piece.size(), m = block.points.size();
    std::vector<bool> flags(n, false);
    for (size_t i = 0; i < n; ++i) {
        for (size_t e = 0; e < m && !flags[i]; ++e) {
            if (!block.streetEdges[e]) continue;
            Vec2f a = block.points[e], b = block.points[(e + 1) % m];
            flags[i] = distanceToSegment(piece[i], a, b) < kOnEdge &&
                       distanceToSegment(piece[(i + 1) % n], a, b) < kOnEdge;
        }
    }
    return flags;
}

double edgeLength(const std::vector<Vec2f> &piece, size_t edge) {
    Vec2f a = piece[edge], b = piece[(edge + 1) % piece.size()];
    return std::hypot(double(b.x) - a.x, double(b.y) - a.y);
}

bool isRightAngle(const std::vector<Vec2f> &piece, size_t edge, size_t neighbour) {
    size_t n = piece.size();
    Vec2f a = piece[edge], b = piece[(edge + 1) % n], c = piece[neighbour], d = piece[(neighbour + 1) % n];
    double cosine = ((double(b.x) - a.x) * (double(d.x) - c.x) + (double(b.y) - a.y) * (double(d.y) - c.y)) /
                    (edgeLength(piece, edge) * edgeLength(piece, neighbour));
    return std::abs(cosine) < kRightAngleCosine;
}

int rightAngles(const std::vector<Vec2f> &piece, size_t edge) {
    size_t n = piece.size();
    return int(isRightAngle(piece, edge, (edge + n - 1) % n)) + int(isRightAngle(piece, edge, (edge + 1) % n));
}

// Thesis step 3: of the two longest edges, the one with more right angles to its neighbours;
// on a tie the longer.
size_t splitEdge(const std::vector<Vec2f> &piece) {
    std::vector<size_t> edges(piece.size());
    for (size_t i = 0; i < edges.size(); ++i) edges[i] = i;
    std::partial_sort(edges.begin(), edges.begin() + 2, edges.end(), [&](size_t a, size_t b) {
        return edgeLength(piece, a) > edgeLength(piece, b);
    });
    return rightAngles(piece, edges[1]) > rightAngles(piece, edges[0]) ? edges[1] : edges[0];
}

// The half-plane left of the line through `on` along `along`, as a quadrilateral of side
// 2 · `reach` (the piece lies well within reach of `on`).
Polygon halfPlane(Point on, Kernel::Vector_2 along, double reach) {
    Kernel::Vector_2 left = along.perpendicular(CGAL::COUNTERCLOCKWISE);
    std::vector<Point> corners{on - along * reach, on + along * reach, on + along * reach + left * reach,
                               on - along * reach + left * reach};
    return Polygon(corners.begin(), corners.end());
}

// Back to float, with points that rounding merged dropped.
std::vector<Vec2f> toFloat(const Polygon &polygon) {
    std::vector<Vec2f> points;
    for (const Point &p : polygon.vertices()) {
        Vec2f q{float(CGAL::to_double(p.x())), float(CGAL::to_double(p.y()))};
        if (points.empty() || q.x != points.back().x || q.y != points.back().y) points.push_back(q);
    }
    while (points.size() > 1 && points.front().x == points.back().x && points.front().y == points.back().y) {
        points.pop_back();
    }
    return points;
}

class RecursiveSplit {
  public:
    RecursiveSplit(const Block &block, const LotSettings &settings, uint32_t blockId,
                   const std::optional<FileLoc> &loc)
        : block_(block), settings_(settings), blockId_(blockId), loc_(loc) {}

    // `key` identifies the piece: the root's from seed and block, each child's from its parent's
    // and its place among the parent's pieces, so every cut is a pure function of them.
    void split(const std::vector<Vec2f> &piece, uint32_t key, int depth) {
        std::vector<bool> flags = streetFlags(piece, block_);
        // Thesis step 1: only pieces with a street edge are split, and only they are kept.
        if (std::find(flags.begin(), flags.end(), true) == flags.end()) return;
        if (lots::polygonArea(piece) <= settings_.maxLotArea) {
            if (lots_.size() == kMaxLotsPerBlock) {
                lots::fail(loc_, fmt::format("block {} would be cut into more than {} lots (MaxLotArea {} m²)",
                                             blockId_, kMaxLotsPerBlock, settings_.maxLotArea));
            }
            lots_.push_back({piece, std::move(flags), block_.base});
            return;
        }
        if (depth == kMaxLotRecursion) {
            lots::fail(loc_, fmt::format("block {} needs lots split more than {} times to reach MaxLotArea {} m²",
                                         blockId_, kMaxLotRecursion, settings_.maxLotArea));
        }
        std::vector<std::vector<Vec2f>> pieces = halves(piece, key);
        for (size_t i = 0; i < pieces.size(); ++i) split(pieces[i], hashValues({key, uint32_t(i)}), depth + 1);
    }

    std::vector<Footprint> takeLots() { return std::move(lots_); }

  private:
    // The piece cut by the perpendicular to its split edge, at a point drawn near the middle; a
    // concave piece may fall into more than two.
    std::vector<std::vector<Vec2f>> halves(const std::vector<Vec2f> &piece, uint32_t key) const {
        size_t edge = splitEdge(piece);
        Vec2f a = piece[edge], b = piece[(edge + 1) % piece.size()];
        float t = lots::normalBetween(kCutFrom, kCutTo, key);
        Point on(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        double length = edgeLength(piece, edge);
        Kernel::Vector_2 along(-(double(b.y) - a.y) / length, (double(b.x) - a.x) / length);  // across the edge
        Polygon polygon;
        for (Vec2f p : piece) polygon.push_back(Point(p.x, p.y));
        CGAL::Bbox_2 box = polygon.bbox();
        double reach = 2 * (box.xmax() - box.xmin() + box.ymax() - box.ymin());
        std::vector<PolygonWithHoles> parts;
        CGAL::intersection(polygon, halfPlane(on, along, reach), std::back_inserter(parts));
        CGAL::intersection(polygon, halfPlane(on, -along, reach), std::back_inserter(parts));
        std::vector<std::vector<Vec2f>> pieces;
        for (const PolygonWithHoles &part : parts) {
            std::vector<Vec2f> points = toFloat(part.outer_boundary());
            if (points.size() >= 3) pieces.push_back(std::move(points));
        }
        return pieces;
    }

    const Block &block_;
    const LotSettings &settings_;
    uint32_t blockId_;
    const std::optional<FileLoc> &loc_;
    std::vector<Footprint> lots_;
};

}  // namespace

std::vector<Footprint> recursiveLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                     const std::optional<FileLoc> &loc) {
    lots::checkBlock(block, loc);
    checkLotSettings(settings, loc);
    RecursiveSplit split(block, settings, blockId, loc);
    split.split(block.points, hashValues({seed, blockId}), 0);
    return filterLots(split.takeLots(), settings, seed, blockId);
}

}  // namespace veduta
