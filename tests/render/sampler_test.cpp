#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "render/sampler.h"

namespace veduta {
namespace {

// The unscrambled first two dimensions are the Sobol sequence in natural (not Gray-code)
// index order: point i is the XOR of the direction numbers of i's set bits.
TEST(Sampler, SobolPointsMatchTheSequence) {
    const float first[8][2] = {{0, 0},           {0.5f, 0.5f},     {0.25f, 0.75f},   {0.75f, 0.25f},
                               {0.125f, 0.625f}, {0.625f, 0.125f}, {0.375f, 0.375f}, {0.875f, 0.875f}};
    for (uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(float(sobolSample(i, 0)) * 0x1p-32f, first[i][0]) << i;
        EXPECT_EQ(float(sobolSample(i, 1)) * 0x1p-32f, first[i][1]) << i;
    }
    // High index bits matter too: bit 31 alone selects the last direction number.
    EXPECT_EQ(sobolSample(1u << 31, 0), 1u);
    EXPECT_EQ(sobolSample(1u << 31, 1), 0xffffffffu);  // row 31 of Pascal's triangle is all odd
}

// next2D works the scrambles out with fewer bit reversals; its points are those of the
// definition in sampler.h, bit for bit.
TEST(Sampler, PointsAreTheScrambledSobolPointsOfTheDefinition) {
    for (uint32_t seed : {0u, 7u, 0xdeadbeefu})
        for (uint32_t pixel = 0; pixel < 40; ++pixel) {
            PixelSeeds seeds(seed, pixel, 3 * pixel + 1);  // shared by the pixel's samples
            for (uint32_t sample : {0u, 1u, 2u, 3u, 17u, 255u, 4096u, 123457u, 0xfffffffeu}) {
                PixelSampler sampler(seed, pixel, 3 * pixel + 1, sample), kept(seeds, sample);
                uint32_t pixelSeed = hashValues({seed * streamTag(RandomStream::Sampler), pixel, 3 * pixel + 1});
                // Past the pairs PixelSeeds keeps, too.
                for (uint32_t pair = 0; pair < PixelSeeds::kPairs + 4; ++pair) {
                    uint32_t pairSeed = hashValues({pixelSeed, pair});
                    uint32_t index = owenScramble(sample, pairSeed);
                    Vec2f expected{bitsToUnitFloat(owenScramble(sobolSample(index, 0), mix32(pairSeed ^ 0xa511e9b3u))),
                                   bitsToUnitFloat(owenScramble(sobolSample(index, 1), mix32(pairSeed ^ 0x63d83595u)))};
                    Vec2f u = sampler.next2D(), v = kept.next2D();
                    ASSERT_EQ(u.x, expected.x) << seed << " " << pixel << " " << sample << " " << pair;
                    ASSERT_EQ(u.y, expected.y) << seed << " " << pixel << " " << sample << " " << pair;
                    ASSERT_EQ(v.x, expected.x) << seed << " " << pixel << " " << sample << " " << pair;
                    ASSERT_EQ(v.y, expected.y) << seed << " " << pixel << " " << sample << " " << pair;
                }
            }
        }
}

TEST(Sampler, IsAPureFunctionOfSeedPixelSampleAndDimension) {
    PixelSampler a(3, 10, 20, 5), b(3, 10, 20, 5);
    for (int d = 0; d < 8; ++d) {
        Vec2f x = a.next2D(), y = b.next2D();
        EXPECT_EQ(x.x, y.x);
        EXPECT_EQ(x.y, y.y);
    }
    Vec2f base = PixelSampler(3, 10, 20, 5).next2D();
    for (PixelSampler other : {PixelSampler(4, 10, 20, 5), PixelSampler(3, 11, 20, 5), PixelSampler(3, 10, 21, 5),
                               PixelSampler(3, 10, 20, 6)}) {
        Vec2f v = other.next2D();
        EXPECT_TRUE(v.x != base.x || v.y != base.y);
    }
}

// A path vertex takes its pairs at once and works out only some, in any order: each is the
// pair that consuming them one by one gives, and the pairs after them keep their place.
TEST(Sampler, TakenPairsAreThoseOfConsumingInOrder) {
    PixelSeeds seeds(5, 12, 34);
    PixelSampler inOrder(5, 12, 34, 9), taken(seeds, 9);
    std::vector<Vec2f> expected;
    for (int k = 0; k < 5; ++k) expected.push_back(inOrder.next2D());
    uint32_t first = taken.take(4);
    EXPECT_EQ(first, 0u);
    for (uint32_t k : {3u, 1u}) {
        Vec2f u = taken.at(first + k);
        EXPECT_EQ(u.x, expected[k].x);
        EXPECT_EQ(u.y, expected[k].y);
    }
    Vec2f after = taken.next2D();
    EXPECT_EQ(after.x, expected[4].x);
    EXPECT_EQ(after.y, expected[4].y);
}

// The first 2^k samples of a pixel are a (0, k, 2)-net: one point in each of the 2^k
// elementary intervals of any shape. Checked for the 4 x 4 and 16 x 1 grids of 16 points.
TEST(Sampler, PowerOfTwoPrefixesAreStratified) {
    for (uint32_t pixel = 0; pixel < 20; ++pixel) {
        for (int pair = 0; pair < 3; ++pair) {
            std::set<int> squares, columns, rows;
            for (uint32_t s = 0; s < 16; ++s) {
                PixelSampler sampler(1, pixel, 7, s);
                Vec2f u{};
                for (int k = 0; k <= pair; ++k) u = sampler.next2D();
                ASSERT_GE(u.x, 0.0f);
                ASSERT_LT(u.x, 1.0f);
                squares.insert(int(u.x * 4) * 4 + int(u.y * 4));
                columns.insert(int(u.x * 16));
                rows.insert(int(u.y * 16));
            }
            EXPECT_EQ(squares.size(), 16u);
            EXPECT_EQ(columns.size(), 16u);
            EXPECT_EQ(rows.size(), 16u);
        }
    }
}

TEST(Sampler, PairsOfOnePixelAreDecorrelated) {
    // Dimension pairs use independent scrambles: pair 0 and pair 1 of the same sample differ.
    int same = 0;
    for (uint32_t s = 0; s < 256; ++s) {
        PixelSampler sampler(0, 3, 3, s);
        Vec2f a = sampler.next2D(), b = sampler.next2D();
        same += std::abs(a.x - b.x) < 1e-3f;
    }
    EXPECT_LT(same, 8);
}

}  // namespace
}  // namespace veduta
