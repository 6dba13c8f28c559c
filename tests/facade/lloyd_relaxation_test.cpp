#include "facade/lloyd_relaxation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A 10 m × 3 m wall with a door standing on its foot and a window (the cyclopean golden scene).
WallFace wallWithDoorAndWindow() {
    return {rectangle(0, 0, 10, 3), {rectangle(2, 0, 3, 2.2), rectangle(5, 1, 6.2, 2.2)}};
}

TEST(WallRegion, IsTheOutlineMinusTheOpenings) {
    WallRegion region(wallWithDoorAndWindow());
    EXPECT_NEAR(region.area(), 30 - 2.2 - 1.44, 1e-12);
    // The door notches the outline; the window is a hole.
    ASSERT_EQ(region.pieces().size(), 1u);
    EXPECT_EQ(region.pieces()[0].outline.size(), 8u);
    ASSERT_EQ(region.pieces()[0].holes.size(), 1u);
    EXPECT_TRUE(region.contains({1, 1}));
    EXPECT_FALSE(region.contains({2.5, 1}));
    EXPECT_FALSE(region.contains({5.5, 1.5}));
    EXPECT_FALSE(region.contains({0, 1}));  // on the boundary
}

TEST(WallRegion, TakesClockwiseOpeningsAsWell) {
    WallFace wall{rectangle(0, 0, 4, 4), {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}};
    EXPECT_NEAR(WallRegion(wall).area(), 15, 1e-12);
}

TEST(WallRegion, ContainsTheIslandWithinAHoleOfAnotherPiece) {
    // Four openings ringing the square [3, 7]² leave it an island in the hole [2, 8]² of the rest
    // of the wall. The point test stopped at the first piece whose hole held the point.
    WallFace wall{rectangle(0, 0, 10, 10),
                  {rectangle(2, 2, 8, 3), rectangle(2, 7, 8, 8), rectangle(2, 2, 3, 8), rectangle(7, 2, 8, 8)}};
    WallRegion region(wall);
    ASSERT_EQ(region.pieces().size(), 2u);
    EXPECT_NEAR(region.area(), 100 - 36 + 16, 1e-12);
    EXPECT_TRUE(region.contains({5, 5}));
    EXPECT_TRUE(region.contains({1, 1}));
    EXPECT_FALSE(region.contains({2.5, 5}));
    // A cell wholly on the island is kept whole, not dropped.
    EXPECT_NEAR(area(region.clip(rectangle(4, 4, 6, 6))), 4, 1e-12);
}

TEST(WallRegion, ClipsAConvexPolygonToTheWall) {
    WallRegion region(wallWithDoorAndWindow());
    // Wholly inside: the polygon itself.
    ClippedCell inside = region.clip(rectangle(0.5, 0.5, 1.5, 1.5));
    ASSERT_EQ(inside.size(), 1u);
    EXPECT_NEAR(area(inside), 1, 1e-12);
    // Across the door's jamb: the door's part is cut away.
    EXPECT_NEAR(area(region.clip(rectangle(1.5, 0.5, 2.5, 1.5))), 0.5, 1e-12);
    // Around the whole window: a piece with a hole.
    ClippedCell around = region.clip(rectangle(4.5, 0.5, 6.5, 2.5));
    ASSERT_EQ(around.size(), 1u);
    EXPECT_EQ(around[0].holes.size(), 1u);
    EXPECT_NEAR(area(around), 4 - 1.44, 1e-12);
    // Across the door from jamb to jamb: two pieces.
    EXPECT_EQ(region.clip(rectangle(1.5, 0.5, 3.5, 1.5)).size(), 2u);
    EXPECT_TRUE(region.clip(rectangle(2.2, 0.2, 2.8, 1)).empty());
}

TEST(WallRegion, MeasuresTheClippedPartWithoutBooleans) {
    WallRegion region(wallWithDoorAndWindow());
    // Around the window: the square's moments less the window's.
    WallRegion::Moments around = region.moments(rectangle(4.5, 0.5, 6.5, 2.5), {5.5, 1.5});
    EXPECT_NEAR(around.area, 2.56, 1e-12);
    EXPECT_NEAR(around.centroid.x, (4 * 5.5 - 1.44 * 5.6) / 2.56, 1e-12);
    EXPECT_NEAR(around.centroid.y, (4 * 1.5 - 1.44 * 1.6) / 2.56, 1e-12);
    double square = 2.0 * 2 * (4 + 4) / 12, window = 1.44 * (1.44 + 1.44) / 12 + 1.44 * (0.1 * 0.1 + 0.1 * 0.1);
    EXPECT_NEAR(around.secondMoment, square - window, 1e-12);
    // Across the door from jamb to jamb: two pieces, 0.5 m² each.
    WallRegion::Moments across = region.moments(rectangle(1.5, 0.5, 3.5, 1.5), {0, 0});
    EXPECT_NEAR(across.area, 1, 1e-12);
    EXPECT_NEAR(across.centroid.x, 2.5, 1e-12);
    EXPECT_NEAR(across.centroid.y, 1, 1e-12);
}

TEST(ClipToHalfPlane, KeepsThePartOnTheInnerSide) {
    std::vector<Vec2d> kept = clipToHalfPlane(rectangle(0, 0, 2, 1), {1, 0}, 0.5);
    EXPECT_NEAR(area(RegionPiece{kept, {}}), 0.5, 1e-15);
    for (Vec2d p : kept) EXPECT_LE(p.x, 0.5);
}

TEST(ClippedVoronoiCells, PartitionTheWallAmongTheNearestSeeds) {
    WallRegion region(wallWithDoorAndWindow());
    std::vector<Vec2d> seeds;
    for (int i = 0; i < 40; ++i) seeds.push_back({0.13 + 0.247 * i, 0.1 + std::fmod(0.731 * i, 2.8)});
    std::vector<ClippedCell> cells = clippedVoronoiCells(region, seeds);
    ASSERT_EQ(cells.size(), seeds.size());
    double total = 0;
    for (size_t i = 0; i < cells.size(); ++i) {
        total += area(cells[i]);
        for (const RegionPiece &piece : cells[i]) {
            for (Vec2d corner : piece.outline) {
                for (Vec2d other : seeds) EXPECT_LE(length(corner - seeds[i]), length(corner - other) + 1e-9);
            }
        }
    }
    EXPECT_NEAR(total, region.area(), 1e-9);
}

TEST(ClippedVoronoiCells, GiveARepeatedSeedNoSecondCell) {
    WallRegion region(WallFace{rectangle(0, 0, 1, 1), {}});
    std::vector<ClippedCell> cells = clippedVoronoiCells(region, {{0.25, 0.5}, {0.75, 0.5}, {0.75, 0.5}});
    EXPECT_NEAR(area(cells[0]), 0.5, 1e-15);
    EXPECT_NEAR(area(cells[1]) + area(cells[2]), 0.5, 1e-15);
    EXPECT_TRUE(cells[1].empty() || cells[2].empty());
}

TEST(RelaxLloyd, MovesEachSeedToItsCellsCentroid) {
    // Unit square, seeds at x = 0.2 and 0.6: the bisector x = 0.4 gives centroids x = 0.2 and 0.7.
    WallRegion region(WallFace{rectangle(0, 0, 1, 1), {}});
    LloydResult result = relaxLloyd(region, {{0.2, 0.5}, {0.6, 0.5}}, 0, {1, 0});
    ASSERT_EQ(result.meanShifts.size(), 1u);
    EXPECT_NEAR(result.meanShifts[0], 0.05, 1e-15);
    EXPECT_NEAR(result.seeds[1].x, 0.7, 1e-15);
    EXPECT_NEAR(result.seeds[1].y, 0.5, 1e-15);
    // ∫|x − s|² over [0, 0.4] × [0, 1] around (0.2, 0.5) and over [0.4, 1] × [0, 1] around (0.6, 0.5).
    double before = (0.4 * 0.4 * 0.4 / 12 + 0.4 / 12) + (0.6 * (0.6 * 0.6 / 12 + 0.01) + 0.6 / 12);
    EXPECT_NEAR(result.energies[0], before, 1e-15);
}

TEST(RelaxLloyd, ConvergesToTheQuadrantCentresOfASquare) {
    WallRegion region(WallFace{rectangle(0, 0, 1, 1), {}});
    LloydResult result = relaxLloyd(region, {{0.2, 0.3}, {0.7, 0.2}, {0.3, 0.8}, {0.8, 0.7}}, 0, {200, 1e-12});
    EXPECT_LT(result.meanShifts.size(), 200u);  // stopped by the threshold
    const Vec2d expected[] = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(result.seeds[i].x, expected[i].x, 1e-9);
        EXPECT_NEAR(result.seeds[i].y, expected[i].y, 1e-9);
    }
}

TEST(RelaxLloyd, NeverRaisesTheEnergyAndKeepsFixedSeeds) {
    WallRegion region(wallWithDoorAndWindow());
    std::vector<Vec2d> seeds{{1.7, 2.5}, {2.3, 2.5}};  // fixed
    for (int i = 0; i < 60; ++i) seeds.push_back({0.05 + 0.165 * i, 0.05 + std::fmod(0.377 * i, 2.9)});
    LloydResult result = relaxLloyd(region, seeds, 2, {30, 0});
    ASSERT_EQ(result.meanShifts.size(), 30u);
    ASSERT_EQ(result.energies.size(), 31u);
    for (size_t i = 1; i < result.energies.size(); ++i) {
        EXPECT_LE(result.energies[i], result.energies[i - 1] * (1 + 1e-12)) << "step " << i;
    }
    EXPECT_LT(result.meanShifts.back(), result.meanShifts.front() / 5);
    EXPECT_EQ(result.seeds[0], seeds[0]);
    EXPECT_EQ(result.seeds[1], seeds[1]);
    double total = 0;
    for (const ClippedCell &cell : result.cells) total += area(cell);
    EXPECT_NEAR(total, region.area(), 1e-9);
}

TEST(RelaxLloyd, StopsAtTheMaximumSteps) {
    WallRegion region(WallFace{rectangle(0, 0, 1, 1), {}});
    LloydResult result = relaxLloyd(region, {{0.1, 0.1}, {0.2, 0.15}, {0.9, 0.8}}, 0, {3, 0});
    EXPECT_EQ(result.meanShifts.size(), 3u);
    EXPECT_EQ(relaxLloyd(region, {{0.1, 0.1}}, 0, {0, 0}).meanShifts.size(), 0u);
}

}  // namespace
}  // namespace veduta
