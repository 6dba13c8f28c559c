// The plane split into tiles, each met by at most so many of a set of boxes: a k-d split at the
// middle of a tile's longer side. The street surfaces are joined tile by tile
// (street_regions.h), each tile from the pieces that reach it, so that their work grows with
// the town instead of as one union of a whole network does (issue 21).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace veduta {

// A closed box: its edges belong to it.
struct Box2d {
    double lowX = 0, lowY = 0, highX = 0, highY = 0;
};

inline bool meet(const Box2d &a, const Box2d &b) {
    return a.lowX <= b.highX && b.lowX <= a.highX && a.lowY <= b.highY && b.lowY <= a.highY;
}

// The smallest box holding both.
Box2d around(const Box2d &a, const Box2d &b);

struct BoxTile {
    Box2d box;
    std::vector<uint32_t> boxes;  // those meeting it (touching counts), ascending
};

// A tile is split no more often than this, whatever its boxes (a town is some km across: 2^-12
// of it is under a metre).
inline constexpr int kMaxTileSplits = 24;

// Tiles covering `extent` that share edges but do not overlap, each with the indices of the
// `boxes` that meet it. A tile met by more than `maxBoxes` is halved at the middle (so that
// neighbouring tiles share their edge exactly) across its longer side, or across the other where
// the halves would together be met by more than 1.5 times its boxes (many cross the middle);
// where both would, or after kMaxTileSplits, it stays whole. The tiles come lower half first,
// depth first: one order for one input.
std::vector<BoxTile> splitIntoTiles(const Box2d &extent, const std::vector<Box2d> &boxes, size_t maxBoxes);

}  // namespace veduta
