// CityEngine's recursive OBB subdivision (Vanegas et al. 2012, anchors-procedural.md §3.4):
// pieces are split across the longer axis of their minimum-area bounding rectangle until they
// are at most MaxLotArea.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>

#include <algorithm>
#include <cmath>

#include "city/lot_subdivision.h"
#include "city/recursive_split.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

using lots::Piece;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

// Where the cut crosses the axis, as a fraction of its length: normally distributed around the
// middle, as Müller's split (Vanegas jitters by ω times the shorter side and gives no ω).
constexpr float kCutFrom = 0.3f, kCutTo = 0.7f;

struct Axis {
    double x = 0, y = 0;  // a side of the rectangle, its full length

    double length() const { return std::hypot(x, y); }
};

// The minimum-area rectangle round a piece (CGAL's min_rectangle_2 on its convex hull).
struct OrientedBox {
    double middleX = 0, middleY = 0;
    Axis longer, shorter;
};

OrientedBox orientedBox(const Piece &piece) {
    std::vector<Point> points, hull, corners;
    for (Vec2f p : piece) points.emplace_back(p.x, p.y);
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
    CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(corners));
    Axis a{corners[1].x() - corners[0].x(), corners[1].y() - corners[0].y()};
    Axis b{corners[2].x() - corners[1].x(), corners[2].y() - corners[1].y()};
    if (a.length() < b.length()) std::swap(a, b);
    return {(corners[0].x() + corners[2].x()) / 2, (corners[0].y() + corners[2].y()) / 2, a, b};
}

// The piece cut by a line along `along` that crosses `across` at a fraction drawn near its
// middle.
std::vector<Piece> cutAcross(const Piece &piece, const OrientedBox &box, const Axis &across, const Axis &along,
                             uint32_t key) {
    double offset = lots::normalBetween(kCutFrom, kCutTo, key) - 0.5;
    Vec2f on{float(box.middleX + across.x * offset), float(box.middleY + across.y * offset)};
    double length = along.length();
    lots::CutSides sides = lots::cutPiece(piece, {on, along.x / length, along.y / length});
    sides.left.insert(sides.left.end(), sides.right.begin(), sides.right.end());
    return sides.left;
}

bool allFaceAStreet(const std::vector<Piece> &parts, const Block &block) {
    return std::all_of(parts.begin(), parts.end(), [&](const Piece &part) { return lots::hasStreetEdge(part, block); });
}

// Across the longer axis; where a part would lose street access, across the shorter one instead
// (Vanegas turns the split by 90°), unless that loses it too.
std::vector<Piece> obbSplit(const Piece &piece, uint32_t key, const Block &block) {
    OrientedBox box = orientedBox(piece);
    std::vector<Piece> parts = cutAcross(piece, box, box.longer, box.shorter, key);
    if (allFaceAStreet(parts, block)) return parts;
    uint32_t turnedKey = hashValues({key, streamTag(RandomStream::LotObbTurned)});
    std::vector<Piece> turned = cutAcross(piece, box, box.shorter, box.longer, turnedKey);
    return allFaceAStreet(turned, block) ? turned : parts;
}

}  // namespace

std::vector<Footprint> obbLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                               const std::optional<FileLoc> &loc) {
    lots::checkBlock(block, loc);
    checkLotSettings(settings, loc);
    lots::SplitRule rule = [&](const Piece &piece, uint32_t key) { return obbSplit(piece, key, block); };
    return filterLots(lots::splitRecursively(block, settings, seed, blockId, loc, rule), settings, seed, blockId);
}

}  // namespace veduta
