#include "geo/height_queries.h"

#include <cmath>

#include <gtest/gtest.h>

namespace veduta {
namespace {

HeightGrid grid3x3() {
    HeightGrid grid;
    grid.west = 500000.5;
    grid.south = 5600000.5;
    grid.spacing = 2;
    grid.columns = grid.rows = 3;
    grid.heights = {10.1f, 11.7f, 9.3f,   //
                    12.9f, 8.4f,  13.3f,  //
                    7.7f,  14.2f, 10.6f};
    return grid;
}

MapPoint at(const HeightGrid &grid, double column, double row) {
    return {grid.west + column * grid.spacing, grid.south + row * grid.spacing};
}

TEST(HeightQueries, ExactAtNodes) {
    HeightGrid grid = grid3x3();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(bilinearHeight(grid, grid.nodePoint(c, r)), double(grid.node(c, r))) << c << ", " << r;
            EXPECT_EQ(surfaceHeight(grid, grid.nodePoint(c, r)), double(grid.node(c, r))) << c << ", " << r;
        }
    }
}

// Map coordinates near 5.6·10⁶ m resolve 10⁻⁹ m, so the position within a cell is known to
// about 5·10⁻¹⁰ of a spacing; heights follow to 10⁻⁸ m here.
TEST(HeightQueries, LinearAlongGridLines) {
    HeightGrid grid = grid3x3();
    for (double t : {0.1, 0.5, 0.8}) {
        double expected = grid.node(1, 1) + t * (double(grid.node(2, 1)) - grid.node(1, 1));
        EXPECT_NEAR(*bilinearHeight(grid, at(grid, 1 + t, 1)), expected, 1e-8);
        EXPECT_NEAR(*surfaceHeight(grid, at(grid, 1 + t, 1)), expected, 1e-8);
        expected = grid.node(2, 0) + t * (double(grid.node(2, 1)) - grid.node(2, 0));
        EXPECT_NEAR(*bilinearHeight(grid, at(grid, 2, t)), expected, 1e-8);
        EXPECT_NEAR(*surfaceHeight(grid, at(grid, 2, t)), expected, 1e-8);
    }
}

// A cell with only its north-east corner raised tells the diagonals apart: on the SW–NE
// diagonal the centre is halfway up, on the other it would be at the bottom.
TEST(HeightQueries, SurfaceSplitsCellsSouthWestToNorthEast) {
    HeightGrid grid;
    grid.spacing = 1;
    grid.columns = grid.rows = 2;
    grid.heights = {0, 0, 0, 4};
    EXPECT_DOUBLE_EQ(*surfaceHeight(grid, {0.5, 0.5}), 2);
    EXPECT_DOUBLE_EQ(*bilinearHeight(grid, {0.5, 0.5}), 1);
    EXPECT_DOUBLE_EQ(*surfaceHeight(grid, {0.75, 0.25}), 1);  // south-east triangle: (0,0) (1,0) (1,1)
    EXPECT_DOUBLE_EQ(*surfaceHeight(grid, {0.25, 0.75}), 1);  // north-west triangle: (0,0) (1,1) (0,1)
    EXPECT_DOUBLE_EQ(*surfaceHeight(grid, {0.9, 0.1}), 0.4);
}

TEST(HeightQueries, NothingOutsideOrOverHoles) {
    HeightGrid grid = grid3x3();
    EXPECT_FALSE(bilinearHeight(grid, at(grid, -0.01, 1)));
    EXPECT_FALSE(surfaceHeight(grid, at(grid, 1, 2.01)));
    EXPECT_TRUE(surfaceHeight(grid, at(grid, 2, 2)));
    grid.node(2, 2) = NAN;
    EXPECT_FALSE(bilinearHeight(grid, at(grid, 1.5, 1.5)));
    EXPECT_FALSE(surfaceHeight(grid, at(grid, 1.2, 1.9)));
    EXPECT_TRUE(surfaceHeight(grid, at(grid, 0.5, 1.5)));
}

}  // namespace
}  // namespace veduta
