#include "city/box_tiles.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace veduta {

Box2d around(const Box2d &a, const Box2d &b) {
    return {std::min(a.lowX, b.lowX), std::min(a.lowY, b.lowY), std::max(a.highX, b.highX), std::max(a.highY, b.highY)};
}

namespace {

// Those of `candidates` (the parent's, ascending) that meet `box`: ascending too.
std::vector<uint32_t> meeting(const Box2d &box, const std::vector<Box2d> &boxes,
                              const std::vector<uint32_t> &candidates) {
    std::vector<uint32_t> kept;
    for (uint32_t i : candidates)
        if (meet(box, boxes[i])) kept.push_back(i);
    return kept;
}

// The two halves of `tile` across x (at its middle) or across y.
std::pair<BoxTile, BoxTile> halves(const BoxTile &tile, bool acrossX, const std::vector<Box2d> &boxes) {
    Box2d low = tile.box, high = tile.box;
    if (acrossX) {
        low.highX = high.lowX = (tile.box.lowX + tile.box.highX) / 2;
    } else {
        low.highY = high.lowY = (tile.box.lowY + tile.box.highY) / 2;
    }
    return {{low, meeting(low, boxes, tile.boxes)}, {high, meeting(high, boxes, tile.boxes)}};
}

void split(BoxTile tile, const std::vector<Box2d> &boxes, size_t maxBoxes, int splits, std::vector<BoxTile> &out) {
    if (tile.boxes.size() > maxBoxes && splits < kMaxTileSplits) {
        bool wide = tile.box.highX - tile.box.lowX >= tile.box.highY - tile.box.lowY;
        for (bool acrossX : {wide, !wide}) {
            auto [lower, higher] = halves(tile, acrossX, boxes);
            // Boxes across the middle meet both halves: where more than half of them do (long
            // streets across the tile), splitting would multiply the work instead of sharing it.
            if (2 * (lower.boxes.size() + higher.boxes.size()) > 3 * tile.boxes.size()) continue;
            split(std::move(lower), boxes, maxBoxes, splits + 1, out);
            split(std::move(higher), boxes, maxBoxes, splits + 1, out);
            return;
        }
    }
    out.push_back(std::move(tile));
}

}  // namespace

std::vector<BoxTile> splitIntoTiles(const Box2d &extent, const std::vector<Box2d> &boxes, size_t maxBoxes) {
    std::vector<uint32_t> all(boxes.size());
    std::iota(all.begin(), all.end(), 0u);
    std::vector<BoxTile> tiles;
    split({extent, meeting(extent, boxes, all)}, boxes, maxBoxes, 0, tiles);
    return tiles;
}

}  // namespace veduta
