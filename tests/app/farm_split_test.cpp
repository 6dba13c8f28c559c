#include "app/farm_split.h"

#include <algorithm>
#include <stdexcept>

#include <gtest/gtest.h>

namespace veduta {
namespace {

// Every pixel of the image lies in exactly one tile, and every tile has pixels.
void expectExactCover(const std::vector<PixelWindow> &tiles, int width, int height) {
    std::vector<int> covered(size_t(width) * height, 0);
    for (const PixelWindow &t : tiles) {
        ASSERT_FALSE(t.empty());
        ASSERT_TRUE((PixelWindow{0, 0, width, height}.contains(t)));
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) ++covered[size_t(y) * width + x];
    }
    EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }))
        << width << "x" << height << " in " << tiles.size() << " tiles";
}

TEST(FarmSplit, EveryTileCountUpToThePixelCountCoversSmallImages) {
    for (int width = 1; width <= 9; ++width)
        for (int height = 1; height <= 9; ++height)
            for (int count = 1; count <= width * height; ++count) {
                std::vector<PixelWindow> tiles = splitIntoTiles(width, height, count);
                ASSERT_EQ(tiles.size(), size_t(count)) << width << "x" << height;
                expectExactCover(tiles, width, height);
            }
}

TEST(FarmSplit, FourTilesOfAWideImageAreItsQuarters) {
    std::vector<PixelWindow> tiles = splitIntoTiles(96, 54, 4);
    std::vector<PixelWindow> quarters{{0, 0, 48, 27}, {48, 0, 96, 27}, {0, 27, 48, 54}, {48, 27, 96, 54}};
    EXPECT_EQ(tiles, quarters);
}

TEST(FarmSplit, APrimeCountGivesNearlySquareTilesOfNearlyEqualArea) {
    std::vector<PixelWindow> tiles = splitIntoTiles(1920, 1080, 7);
    ASSERT_EQ(tiles.size(), 7u);
    expectExactCover(tiles, 1920, 1080);
    auto [smallest, largest] =
        std::minmax_element(tiles.begin(), tiles.end(), [](auto &a, auto &b) { return a.area() < b.area(); });
    EXPECT_LT(double(largest->area()) / double(smallest->area()), 1.1);
    for (const PixelWindow &t : tiles) {
        double aspect = double(t.width()) / t.height();
        EXPECT_GT(aspect, 0.5);
        EXPECT_LT(aspect, 2.0);
    }
}

TEST(FarmSplit, TallImagesAreSplitIntoRows) {
    std::vector<PixelWindow> tiles = splitIntoTiles(10, 1000, 4);
    ASSERT_EQ(tiles.size(), 4u);
    for (const PixelWindow &t : tiles) EXPECT_EQ(t.width(), 10);
    expectExactCover(tiles, 10, 1000);
}

TEST(FarmSplit, RefusesMoreTilesThanPixels) {
    EXPECT_THROW(splitIntoTiles(4, 3, 13), std::invalid_argument);
    EXPECT_THROW(splitIntoTiles(4, 3, 0), std::invalid_argument);
    EXPECT_NO_THROW(splitIntoTiles(4, 3, 12));
}

TEST(FarmSplit, SampleRangesFollowEachOtherAndDifferByOneAtMost) {
    std::vector<SampleRange> expected{{0, 3}, {3, 3}, {6, 4}};
    EXPECT_EQ(splitSamples(10, 3), expected);
    for (uint32_t spp = 1; spp <= 40; ++spp)
        for (uint32_t count = 1; count <= spp; ++count) {
            std::vector<SampleRange> ranges = splitSamples(spp, count);
            ASSERT_EQ(ranges.size(), count);
            uint32_t next = 0;
            for (const SampleRange &r : ranges) {
                EXPECT_EQ(r.offset, next);
                EXPECT_GE(r.samples, spp / count);
                EXPECT_LE(r.samples, spp / count + 1);
                next += r.samples;
            }
            EXPECT_EQ(next, spp);
        }
}

TEST(FarmSplit, RefusesMoreSampleRangesThanSamples) {
    EXPECT_THROW(splitSamples(4, 5), std::invalid_argument);
    EXPECT_THROW(splitSamples(4, 0), std::invalid_argument);
}

}  // namespace
}  // namespace veduta
