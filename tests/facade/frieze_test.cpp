#include "facade/frieze.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace veduta {
namespace {

// The pool of Fig. 5.28 (L1216): start, mid and end texture of one image.
std::vector<TextureRegion> figure5_28Pool() {
    return parseCorniceDescription(
               R"(Modifications { line, rel, 0, 0.2; arc, abs, 90, 45, 0.5, 0, 1, 2; line, rel, -90, 0.4; }
TextureDescs { "textures/frieze.bmp", 0.0, 0.625, 0.04875, 0.25;
               "textures/frieze.bmp", 0.0, 1.0, 0.5, 0.625;
               "textures/frieze.bmp", 0.953125, 0.625, 1.0, 0.25; })",
               "frieze.txt")
        .textures;
}

TEST(Frieze, MidTilesRunOnWithoutGapBetweenEndPiecesOfTheirAspect) {
    std::vector<TextureRegion> pool = figure5_28Pool();
    std::vector<FriezePiece> pieces = layFrieze(10, 0.4, {0, 1, 2}, pool, 1);
    double start = 0.4 * 0.04875 / 0.375, end = 0.4 * 0.046875 / 0.375, tile = 0.4 * 0.5 / 0.375;
    int tiles = int(std::round((10 - start - end) / tile));
    EXPECT_EQ(tiles, 19);
    ASSERT_EQ(pieces.size(), size_t(tiles + 2));
    EXPECT_EQ(pieces.front().part, FriezePart::Start);
    EXPECT_EQ(pieces.front().texture, 0);
    EXPECT_EQ(pieces.front().from, 0);
    EXPECT_NEAR(pieces.front().to, start, 1e-15);
    EXPECT_EQ(pieces.back().part, FriezePart::End);
    EXPECT_EQ(pieces.back().texture, 2);
    EXPECT_NEAR(pieces.back().from, 10 - end, 1e-15);
    EXPECT_EQ(pieces.back().to, 10);
    double width = (10 - start - end) / tiles;
    for (size_t i = 1; i + 1 < pieces.size(); ++i) {
        EXPECT_EQ(pieces[i].part, FriezePart::Mid);
        EXPECT_EQ(pieces[i].texture, 1);
        EXPECT_NEAR(pieces[i].to - pieces[i].from, width, 1e-12);
    }
    for (size_t i = 0; i + 1 < pieces.size(); ++i) EXPECT_EQ(pieces[i].to, pieces[i + 1].from);
}

TEST(Frieze, TileCountComesClosestToTheMidTexturesAspect) {
    std::vector<TextureRegion> pool = figure5_28Pool();
    // Mid only: tiles 0.5 wide at height 0.375. 1.3 m → 2.6 → 3 tiles; 1.2 m → 2.4 → 2 tiles.
    EXPECT_EQ(layFrieze(1.3, 0.375, {-1, 1, -1}, pool, 1).size(), 3u);
    EXPECT_EQ(layFrieze(1.2, 0.375, {-1, 1, -1}, pool, 1).size(), 2u);
    EXPECT_EQ(layFrieze(0.1, 0.375, {-1, 1, -1}, pool, 1).size(), 1u);
    // An image twice as wide as high makes the tiles twice as wide.
    EXPECT_EQ(layFrieze(2.6, 0.375, {-1, 1, -1}, pool, 2).size(), 3u);
}

TEST(Frieze, ShortStripGetsOnlyShrunkEndPieces) {
    std::vector<TextureRegion> pool = figure5_28Pool();
    double start = 0.4 * 0.04875 / 0.375, end = 0.4 * 0.046875 / 0.375;
    std::vector<FriezePiece> pieces = layFrieze(0.08, 0.4, {0, 1, 2}, pool, 1);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(pieces[0].to, 0.08 * start / (start + end), 1e-15);
    EXPECT_EQ(pieces[1].from, pieces[0].to);
    EXPECT_EQ(pieces[1].to, 0.08);
}

TEST(Frieze, NegativeIndicesLeaveOutOrUntexturePieces) {
    std::vector<TextureRegion> pool = figure5_28Pool();
    std::vector<FriezePiece> pieces = layFrieze(3, 0.4, {0, -1, 2}, pool, 1);
    ASSERT_EQ(pieces.size(), 3u);
    EXPECT_EQ(pieces[1].part, FriezePart::Mid);
    EXPECT_EQ(pieces[1].texture, -1);
    std::vector<FriezePiece> none = layFrieze(0, 0.4, {0, 1, 2}, pool, 1);
    ASSERT_EQ(none.size(), 1u);
    EXPECT_EQ(none[0].texture, 1);
}

TEST(Frieze, TileCountIsLimited) {
    std::vector<TextureRegion> pool = figure5_28Pool();
    try {
        layFrieze(1000, 1e-6, {-1, 1, -1}, pool, 1);
        FAIL() << "no error";
    } catch (const InputError &error) {
        EXPECT_EQ(std::string(error.what()).substr(0, 13), "frieze.txt:3:");
    }
}

}  // namespace
}  // namespace veduta
