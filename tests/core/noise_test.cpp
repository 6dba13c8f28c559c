// The noise of procedural textures: deterministic, bounded, band-limited to the footprint.
#include <gtest/gtest.h>

#include <cmath>

#include "core/noise.h"

namespace veduta {
namespace {

TEST(Noise, GradientNoiseIsZeroOnTheLatticeBoundedAndSeeded) {
    EXPECT_EQ(gradientNoise({3, -7}, 1), 0.0f);
    double most = 0, differ = 0;
    for (int i = 0; i < 4000; ++i) {
        Vec2d p{0.37 * i, 0.11 * i - 50};
        float a = gradientNoise(p, 1);
        EXPECT_EQ(a, gradientNoise(p, 1));
        most = std::max(most, double(std::abs(a)));
        differ += std::abs(a - gradientNoise(p, 2));
    }
    EXPECT_LT(most, 1.0);
    EXPECT_GT(most, 0.3);
    EXPECT_GT(differ / 4000, 0.05);  // another seed, other noise
}

// Octaves finer than the footprint are left out: with a footprint of a quarter, octaves of
// periods 1 and 1/2 remain and the rest (1/4 and finer) are gone, so the sum equals the sum of
// the two coarse octaves alone.
TEST(Noise, FractalNoiseLeavesOutOctavesFinerThanTheFootprint) {
    for (int i = 0; i < 200; ++i) {
        Vec2d p{0.731 * i, 0.377 * i};
        float full = fractalNoise(p, 9, 6, 0.5f, 0.25);
        float coarse = fractalNoise(p, 9, 2, 0.5f, 0) * float((1 + 0.5) / (1 + 0.5 + 0.25 + 0.125 + 0.0625 + 0.03125));
        EXPECT_NEAR(full, coarse, 1e-6) << i;
    }
    // A footprint wider than the coarsest period averages everything away.
    EXPECT_EQ(fractalNoise({1.3, 2.7}, 9, 6, 0.5f, 1.0), 0.0f);
}

TEST(Noise, CellDistancesAreOrderedAndFindTheNearestPoint) {
    for (int i = 0; i < 500; ++i) {
        Vec2d p{0.173 * i, -0.291 * i};
        CellDistances d = cellDistances(p, 4);
        EXPECT_GE(d.nearest, 0);
        EXPECT_LE(d.nearest, d.second);
        EXPECT_LT(d.nearest, 1.5);  // a point in every cell: never farther than a cell's diagonal
        CellDistances again = cellDistances(p, 4);
        EXPECT_EQ(d.cell, again.cell);
    }
}

}  // namespace
}  // namespace veduta
