// The k-d split of the plane into tiles that the street surfaces are joined in.
#include <gtest/gtest.h>

#include <set>

#include "city/box_tiles.h"

namespace veduta {
namespace {

double area(const Box2d &b) { return (b.highX - b.lowX) * (b.highY - b.lowY); }

// A grid of small boxes, a metre across, ten metres apart.
std::vector<Box2d> gridOfBoxes(int columns, int rows) {
    std::vector<Box2d> boxes;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < columns; ++x) boxes.push_back({10.0 * x, 10.0 * y, 10.0 * x + 1, 10.0 * y + 1});
    return boxes;
}

TEST(BoxTiles, TilesCoverTheExtentOnceAndListTheBoxesThatMeetThem) {
    std::vector<Box2d> boxes = gridOfBoxes(20, 15);
    Box2d extent{-5, -5, 200, 150};
    std::vector<BoxTile> tiles = splitIntoTiles(extent, boxes, 16);
    EXPECT_GT(tiles.size(), 300u / 16);
    double covered = 0;
    for (size_t t = 0; t < tiles.size(); ++t) {
        const BoxTile &tile = tiles[t];
        covered += area(tile.box);
        EXPECT_LE(tile.boxes.size(), 16u);
        // Exactly the boxes that meet it, ascending.
        std::vector<uint32_t> expected;
        for (uint32_t b = 0; b < boxes.size(); ++b)
            if (meet(tile.box, boxes[b])) expected.push_back(b);
        EXPECT_EQ(tile.boxes, expected) << t;
        // Tiles share at most an edge.
        for (size_t u = t + 1; u < tiles.size(); ++u) {
            const Box2d &a = tile.box, &b = tiles[u].box;
            bool overlap = a.lowX < b.highX && b.lowX < a.highX && a.lowY < b.highY && b.lowY < a.highY;
            EXPECT_FALSE(overlap) << t << " " << u;
        }
    }
    EXPECT_DOUBLE_EQ(covered, area(extent));
    // Every box is in some tile.
    std::set<uint32_t> listed;
    for (const BoxTile &tile : tiles) listed.insert(tile.boxes.begin(), tile.boxes.end());
    EXPECT_EQ(listed.size(), boxes.size());
}

TEST(BoxTiles, FewBoxesAreOneTile) {
    std::vector<Box2d> boxes = gridOfBoxes(4, 4);
    std::vector<BoxTile> tiles = splitIntoTiles({0, 0, 40, 40}, boxes, 16);
    ASSERT_EQ(tiles.size(), 1u);
    EXPECT_EQ(tiles[0].boxes.size(), 16u);
}

// Boxes that all cross the middle (long streets across the town) are not split: each half would
// do all the work again.
TEST(BoxTiles, BoxesAcrossEveryTileStopTheSplit) {
    std::vector<Box2d> boxes;
    for (int k = 0; k < 50; ++k) boxes.push_back({0, double(k), 100, double(k) + 0.5});
    std::vector<BoxTile> tiles = splitIntoTiles({0, 0, 100, 50}, boxes, 8);
    // Split across y only: each row of tiles holds its own streets.
    for (const BoxTile &tile : tiles) {
        EXPECT_EQ(tile.box.lowX, 0);
        EXPECT_EQ(tile.box.highX, 100);
    }
    EXPECT_GT(tiles.size(), 1u);
}

}  // namespace
}  // namespace veduta
