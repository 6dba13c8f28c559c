// Straight-skeleton subdivision after Vanegas, Kelly, Weber, Halatsch, Aliaga and Müller 2012
// (anchors-procedural.md §3.4, CityEngine's "Skeleton" subdivision): strips of the block's
// straight skeleton along the streets, cut into lots perpendicular to the street.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/create_straight_skeleton_2.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "city/lot_pieces.h"
#include "city/lot_subdivision.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

using lots::ExactPolygon;
using lots::Piece;
using SkeletonKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactPoint = lots::ExactKernel::Point_2;
using Region = CGAL::Polygon_set_2<lots::ExactKernel>;

// Two street edges meeting at a convex corner below this interior angle get a corner lot
// (CityEngine's cornerAngleMax; its default is not documented where we looked).
constexpr double kCornerAngleMaxDegrees = 120;

// The block's interior straight skeleton: the face of each block edge (counter-clockwise, from
// the edge's start) and, for each block point, the skeleton node its bisector runs to.
struct Skeleton {
    std::vector<ExactPolygon> faces;
    std::vector<ExactPoint> nodes;
};

std::optional<Skeleton> skeletonOf(const Block &block) {
    std::vector<SkeletonKernel::Point_2> outline;
    for (Vec2f p : block.points) outline.emplace_back(p.x, p.y);
    auto skeleton = CGAL::create_interior_straight_skeleton_2(outline.begin(), outline.end(), SkeletonKernel());
    if (!skeleton) return std::nullopt;
    size_t n = block.points.size();
    Skeleton result{std::vector<ExactPolygon>(n), std::vector<ExactPoint>(n)};
    for (auto face = skeleton->faces_begin(); face != skeleton->faces_end(); ++face) {
        // The face's halfedge runs along its block edge; the skeleton keeps the block's points.
        auto edge = face->halfedge();
        const SkeletonKernel::Point_2 &start = edge->opposite()->vertex()->point();
        auto index = std::find_if(block.points.begin(), block.points.end(),
                                  [&](Vec2f p) { return double(p.x) == start.x() && double(p.y) == start.y(); });
        if (index == block.points.end()) return std::nullopt;
        size_t i = size_t(index - block.points.begin());
        result.faces[i].push_back(ExactPoint(start.x(), start.y()));
        for (auto h = edge; h->next() != edge; h = h->next()) {
            const SkeletonKernel::Point_2 &p = h->vertex()->point();
            result.faces[i].push_back(ExactPoint(p.x(), p.y()));
        }
        // Up from the edge's end along its bisector: the node the next point's bisector reaches.
        const SkeletonKernel::Point_2 &node = edge->next()->vertex()->point();
        result.nodes[(i + 1) % n] = ExactPoint(node.x(), node.y());
    }
    return result;
}

// A street edge's strip: its region, and the stretch of the edge (metres from its start) that
// still fronts it after the corners were given away.
struct Strip {
    bool own = false;  // the edge has a strip of its own
    Region region;
    double from = 0, to = 0;
};

double edgeLength(const Block &block, size_t edge) {
    Vec2f a = block.points[edge], b = block.points[(edge + 1) % block.points.size()];
    return std::hypot(double(b.x) - a.x, double(b.y) - a.y);
}

// The street edges that get a strip of their own: those of at least MinBuildingLength (shorter
// ones would be lots too narrow to build on), or the longest street edge when none is.
std::vector<bool> stripEdges(const Block &block, float minLength) {
    size_t n = block.points.size();
    std::vector<bool> strips(n, false);
    std::optional<size_t> longest;
    for (size_t e = 0; e < n; ++e) {
        if (!block.streetEdges[e]) continue;
        strips[e] = edgeLength(block, e) >= minLength;
        if (!longest || edgeLength(block, e) > edgeLength(block, *longest)) longest = e;
    }
    if (longest && std::find(strips.begin(), strips.end(), true) == strips.end()) strips[*longest] = true;
    return strips;
}

double interiorAngleDegrees(const Block &block, size_t point) {
    size_t n = block.points.size();
    Vec2f prev = block.points[(point + n - 1) % n], here = block.points[point], next = block.points[(point + 1) % n];
    double ax = double(prev.x) - here.x, ay = double(prev.y) - here.y;
    double bx = double(next.x) - here.x, by = double(next.y) - here.y;
    double angle = std::atan2(bx * ay - by * ax, bx * ax + by * ay);
    return (angle < 0 ? angle + 2 * std::numbers::pi : angle) * 180 / std::numbers::pi;
}

class SkeletonStrips {
  public:
    SkeletonStrips(const Block &block, float minBuildingLength, Skeleton skeleton) :
        block_(block), skeleton_(std::move(skeleton)), strips_(block.points.size()) {
        std::vector<bool> carries = stripEdges(block, minBuildingLength);
        for (size_t e = 0; e < strips_.size(); ++e) {
            if (!carries[e]) continue;
            strips_[e] = {true, Region(skeleton_.faces[e]), 0, edgeLength(block, e)};
        }
    }

    std::vector<Strip> build() {
        size_t n = block_.points.size();
        for (size_t point = 0; point < n; ++point) {
            size_t before = (point + n - 1) % n;
            if (strips_[before].own && strips_[point].own &&
                interiorAngleDegrees(block_, point) < kCornerAngleMaxDegrees) {
                giveCorner(point);
            }
        }
        for (size_t e = 0; e < n; ++e) {
            if (!strips_[e].own) strips_[nearestStrip(e)].region.join(skeleton_.faces[e]);
        }
        return std::move(strips_);
    }

  private:
    // Vanegas' β-strips: at a corner of two streets, the region between the skeleton's diagonal
    // from the corner and the perpendicular dropped from the diagonal's far end onto the shorter
    // street goes to the longer street's strip (to the edge before the corner on a tie). The lot
    // there fronts both streets: the corner lot.
    void giveCorner(size_t point) {
        size_t n = block_.points.size(), before = (point + n - 1) % n;
        bool beforeLonger = edgeLength(block_, before) >= edgeLength(block_, point);
        size_t longer = beforeLonger ? before : point, shorter = beforeLonger ? point : before;
        const ExactPoint &node = skeleton_.nodes[point];
        Vec2f a = block_.points[shorter], b = block_.points[(shorter + 1) % n];
        // Exactly on the street's line: a foot rounded off it would leave a sliver of the strip.
        ExactPoint start(a.x, a.y), end(b.x, b.y);
        ExactPoint foot = lots::ExactKernel::Line_2(start, end).projection(node);
        double along = CGAL::to_double((foot - start) * (end - start)) / edgeLength(block_, shorter);
        ExactPolygon triangle;
        triangle.push_back(ExactPoint(block_.points[point].x, block_.points[point].y));
        triangle.push_back(node);
        triangle.push_back(foot);
        if (triangle.orientation() == CGAL::COLLINEAR) return;
        if (triangle.orientation() == CGAL::CLOCKWISE) triangle.reverse_orientation();
        Region given = strips_[shorter].region;
        given.intersection(triangle);
        strips_[shorter].region.difference(triangle);
        strips_[longer].region.join(given);
        Strip &s = strips_[shorter];
        if (shorter == point) {
            s.from = std::max(s.from, along);
        } else {
            s.to = std::min(s.to, along);
        }
    }

    // The strip a face without one joins: of the strip edges before and after it round the
    // block, the one nearer along the outline from the face's edge's middle; on a tie (a corner
    // cut off symmetrically) the longer, as with corners.
    size_t nearestStrip(size_t edge) const {
        size_t n = block_.points.size(), before = (edge + n - 1) % n, after = (edge + 1) % n;
        double toBefore = edgeLength(block_, edge) / 2, toAfter = toBefore;
        for (; !strips_[before].own; before = (before + n - 1) % n) toBefore += edgeLength(block_, before);
        for (; !strips_[after].own; after = (after + 1) % n) toAfter += edgeLength(block_, after);
        if (toBefore != toAfter) return toBefore < toAfter ? before : after;
        return edgeLength(block_, before) >= edgeLength(block_, after) ? before : after;
    }

    const Block &block_;
    Skeleton skeleton_;
    std::vector<Strip> strips_;
};

// Cuts a strip perpendicular to its street edge at frontages drawn from [MinBuildingLength,
// MaxBuildingLength] along the stretch it fronts; a rest shorter than MinBuildingLength stays
// with the lot before it. Parts of a cut that reach no street (where a strip bends round a
// reflex corner) are left empty.
class StripCutter {
  public:
    StripCutter(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                const std::optional<FileLoc> &loc) :
        block_(block), settings_(settings), seed_(seed), blockId_(blockId), loc_(loc) {}

    void cut(const Strip &strip, size_t edge) {
        std::vector<Piece> rest;
        std::vector<CGAL::Polygon_with_holes_2<lots::ExactKernel>> parts;
        strip.region.polygons_with_holes(std::back_inserter(parts));
        // The faces joined into a strip are neighbours round the outline, so they enclose no hole.
        for (const auto &part : parts) rest.push_back(lots::toPiece(part.outer_boundary()));
        Vec2f start = block_.points[edge], end = block_.points[(edge + 1) % block_.points.size()];
        double length = edgeLength(block_, edge);
        double dx = (double(end.x) - start.x) / length, dy = (double(end.y) - start.y) / length;
        uint32_t draws = 0;
        for (double at = strip.from;;) {
            uint32_t key =
                hashValues({seed_, blockId_, streamTag(RandomStream::LotSkeletonFrontage), uint32_t(edge), draws++});
            at += lots::normalBetween(settings_.minBuildingLength, settings_.maxBuildingLength, key);
            if (strip.to - at < settings_.minBuildingLength) break;
            if (++cuts_ >= kMaxLotsPerBlock) {
                lots::fail(loc_,
                           fmt::format("block {} would be cut into more than {} skeleton lots (MinBuildingLength {} m)",
                                       blockId_, kMaxLotsPerBlock, settings_.minBuildingLength));
            }
            lots::CutLine across{{float(start.x + dx * at), float(start.y + dy * at)}, -dy, dx};
            std::vector<Piece> beyond;
            for (const Piece &piece : rest) {
                lots::CutSides sides = lots::cutPiece(piece, across);
                for (Piece &lot : sides.left) keep(std::move(lot));
                beyond.insert(beyond.end(), sides.right.begin(), sides.right.end());
            }
            rest = std::move(beyond);
        }
        for (Piece &lot : rest) keep(std::move(lot));
    }

    std::vector<Footprint> takeLots() { return std::move(lots_); }

  private:
    void keep(Piece piece) {
        if (piece.size() < 3) return;
        std::vector<bool> flags = lots::streetFlags(piece, block_);
        if (std::find(flags.begin(), flags.end(), true) == flags.end()) return;
        lots_.push_back({std::move(piece), std::move(flags), block_.base});
    }

    const Block &block_;
    const LotSettings &settings_;
    uint32_t seed_, blockId_;
    const std::optional<FileLoc> &loc_;
    size_t cuts_ = 0;  // in all strips; each adds a lot
    std::vector<Footprint> lots_;
};

}  // namespace

std::vector<Footprint> skeletonLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                    const std::optional<FileLoc> &loc) {
    if (!lots::checkedAndOnAStreet(block, settings, loc)) return {};
    std::optional<Skeleton> skeleton = skeletonOf(block);
    if (!skeleton) lots::fail(loc, fmt::format("CGAL could not build the straight skeleton of block {}", blockId));
    std::vector<Strip> strips = SkeletonStrips(block, settings.minBuildingLength, std::move(*skeleton)).build();
    StripCutter cutter(block, settings, seed, blockId, loc);
    for (size_t e = 0; e < strips.size(); ++e) {
        if (strips[e].own) cutter.cut(strips[e], e);
    }
    return filterLots(cutter.takeLots(), settings, seed, blockId);
}

}  // namespace veduta
