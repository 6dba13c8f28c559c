// Bilke's subdivideLot-Mueller (thesis L362–374, after Müller 2001): recursive splits of a
// block until every piece is at most MaxLotArea.
#include <algorithm>
#include <cmath>

#include "city/lot_subdivision.h"
#include "city/recursive_split.h"

namespace veduta {

namespace {

using lots::Piece;

// An angle within this of 90° counts as right when choosing the edge to split.
constexpr double kRightAngleCosine = 0.0872;  // cos 85°
// Where the cut crosses the chosen edge, as a fraction of its length: normally distributed
// around the middle (the thesis gives no σ).
constexpr float kCutFrom = 0.3f, kCutTo = 0.7f;

double edgeLength(const Piece &piece, size_t edge) {
    Vec2f a = piece[edge], b = piece[(edge + 1) % piece.size()];
    return std::hypot(double(b.x) - a.x, double(b.y) - a.y);
}

bool isRightAngle(const Piece &piece, size_t edge, size_t neighbour) {
    size_t n = piece.size();
    Vec2f a = piece[edge], b = piece[(edge + 1) % n], c = piece[neighbour], d = piece[(neighbour + 1) % n];
    double cosine = ((double(b.x) - a.x) * (double(d.x) - c.x) + (double(b.y) - a.y) * (double(d.y) - c.y)) /
        (edgeLength(piece, edge) * edgeLength(piece, neighbour));
    return std::abs(cosine) < kRightAngleCosine;
}

int rightAngles(const Piece &piece, size_t edge) {
    size_t n = piece.size();
    return int(isRightAngle(piece, edge, (edge + n - 1) % n)) + int(isRightAngle(piece, edge, (edge + 1) % n));
}

// Thesis step 3: of the two longest edges, the one with more right angles to its neighbours;
// on a tie the longer.
size_t splitEdge(const Piece &piece) {
    std::vector<size_t> edges(piece.size());
    for (size_t i = 0; i < edges.size(); ++i) edges[i] = i;
    std::partial_sort(edges.begin(), edges.begin() + 2, edges.end(),
                      [&](size_t a, size_t b) { return edgeLength(piece, a) > edgeLength(piece, b); });
    return rightAngles(piece, edges[1]) > rightAngles(piece, edges[0]) ? edges[1] : edges[0];
}

// The piece cut by the perpendicular to its split edge, at a point drawn near the middle; a
// concave piece may fall into more than two.
std::vector<Piece> halves(const Piece &piece, uint32_t key) {
    size_t edge = splitEdge(piece);
    Vec2f a = piece[edge], b = piece[(edge + 1) % piece.size()];
    float t = lots::normalBetween(kCutFrom, kCutTo, key);
    double length = edgeLength(piece, edge);
    lots::CutLine across{
        {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, -(double(b.y) - a.y) / length, (double(b.x) - a.x) / length};
    lots::CutSides sides = lots::cutPiece(piece, across);
    sides.left.insert(sides.left.end(), sides.right.begin(), sides.right.end());
    return sides.left;
}

}  // namespace

std::vector<Footprint> recursiveLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                     const std::optional<FileLoc> &loc) {
    lots::checkBlock(block, loc);
    checkLotSettings(settings, loc);
    return filterLots(lots::splitRecursively(block, settings, seed, blockId, loc, halves), settings, seed, blockId);
}

}  // namespace veduta
