// The procedural ground and pavements (issue 23): their means hold from near to far (a wide
// footprint sees what many close looks average to), the track is where a track is, the
// ground turns to rock on steep slopes and to alpine ground above the tree line, and no tree
// grows on rock or above the tree line.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "geo/pavement_texture.h"
#include "geo/shore_distance.h"
#include "geo/terrain_texture.h"

namespace veduta {
namespace {

Vec3f at(const ProceduralTexture &t, Vec2d p, float footprint) {
    float v[3];
    t.lookup(Vec2f{float(p.x), float(p.y)}, footprint, v, 3);
    return {v[0], v[1], v[2]};
}

// The mean of close looks (1 mm footprints) over a square of `side` metres at `corner`.
Vec3f closeMean(const ProceduralTexture &t, Vec2d corner, double side) {
    constexpr int kSteps = 120;
    Vec3f sum(0.0f);
    for (int j = 0; j < kSteps; ++j)
        for (int i = 0; i < kSteps; ++i)
            sum += at(t, {corner.x + side * (i + 0.5) / kSteps, corner.y + side * (j + 0.5) / kSteps}, 0.001f);
    return sum * (1.0f / (kSteps * kSteps));
}

double luminance(Vec3f c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

TEST(PavementTexture, FarAwayItIsTheMeanOfItsDetail) {
    for (Pavement p : {Pavement::Asphalt, Pavement::Cobbles, Pavement::Concrete, Pavement::Gravel, Pavement::Ballast}) {
        PavementTexture colour(p, PavementMap::Colour, 7);
        // A 1.2 m patch seen close, against the same patch seen through one 1.2 m footprint.
        Vec3f near = closeMean(colour, {0.3, 2.0}, 1.2);
        Vec3f far = at(colour, {0.9, 2.6}, 1.2f);
        EXPECT_NEAR(luminance(far), luminance(near), 0.12 * luminance(near)) << pavementName(p);
    }
}

TEST(PavementTexture, NormalsFaceUpAndTilthAtTheSettsJoints) {
    PavementTexture normal(Pavement::Cobbles, PavementMap::Normal, 7);
    double tilted = 0;
    for (int i = 0; i < 400; ++i) {
        Vec3f n = at(normal, {0.0071 * i, 0.013 * i}, 0.001f) * 2.0f - Vec3f(1.0f);
        EXPECT_NEAR(length(n), 1.0f, 1e-4f);
        EXPECT_GT(n.z, 0.5f);
        tilted = std::max(tilted, double(1 - n.z));
    }
    EXPECT_GT(tilted, 0.05);  // the worn stones' edges
    // Far away the relief is gone: the normal is the surface's.
    Vec3f flat = at(normal, {1, 1}, 2.0f) * 2.0f - Vec3f(1.0f);
    EXPECT_NEAR(flat.z, 1.0f, 1e-3f);
}

TEST(PavementTexture, RailsAndSleepersLieOnTheTrack) {
    PavementTexture ballast(Pavement::Ballast, PavementMap::Colour, 7);
    // On a sleeper (within 0.26 m of every 0.6 m) between the rails: the sleeper's grey.
    Vec3f sleeper = at(ballast, {0.3, 0.6 * 17 + 0.1}, 0.001f);
    EXPECT_NEAR(sleeper.x, 0.42f, 1e-4f);
    // On a rail head, 0.7525 m right of the centre.
    Vec3f rail = at(ballast, {0.7525, 0.6 * 17 + 0.4}, 0.001f);
    EXPECT_NEAR(rail.x, 0.22f, 1e-4f);
    // Beside the track: ballast, darker and redder than the sleepers.
    Vec3f stones = closeMean(ballast, {1.8, 3}, 0.5);
    EXPECT_LT(luminance(stones), 0.35);
    EXPECT_GT(stones.x, stones.z);
    // Two tracks 4.5 m apart: a rail at 2.25 + 0.7525 m.
    PavementTexture twin(Pavement::Ballast, PavementMap::Colour, 7, 2);
    EXPECT_NEAR(at(twin, {3.0025, 0.6 * 5 + 0.4}, 0.001f).x, 0.22f, 1e-4f);
}

// A DGM 200 m square at 10 m: flat in the west half, a 60° slope in the east, the north row
// high in the Alps.
std::shared_ptr<const HeightGrid> testGrid() {
    auto grid = std::make_shared<HeightGrid>();
    grid->west = 500000, grid->south = 5300000, grid->spacing = 10, grid->columns = 21, grid->rows = 21;
    for (int r = 0; r < grid->rows; ++r)
        for (int c = 0; c < grid->columns; ++c) {
            double h = c <= 10 ? 400 : 400 + (c - 10) * 10 * std::tan(60 * M_PI / 180);
            grid->heights.push_back(float(r == 20 ? 2200 : r == 19 ? 2200 - 1e-3 : h));
        }
    return grid;
}

TEST(TerrainTexture, RockOnSteepSlopesAlpineAboveTheTreeLine) {
    std::shared_ptr<const HeightGrid> grid = testGrid();
    LocalFrame frame{{500000, 5300000}};
    Vec3f meadow{0.13f, 0.23f, 0.06f};
    TerrainTexture grass(LandClass::Grassland, meadow, grid, frame, nullptr, 3);
    Vec3f flat = closeMean(grass, {30, 30}, 20);
    Vec3f steep = closeMean(grass, {150, 30}, 20);
    Vec3f high = closeMean(grass, {30, 191}, 8);
    // Flat meadow stays green about its albedo; the 60° slope is grey rock; the Alps brown.
    EXPECT_GT(flat.y, flat.x);
    EXPECT_NEAR(luminance(flat), luminance(meadow), 0.35 * luminance(meadow));
    EXPECT_NEAR(steep.x, steep.y, 0.03);
    EXPECT_NEAR(steep.y, steep.z, 0.03);
    EXPECT_GT(high.x, high.y * 0.9f);
    EXPECT_LT(std::abs(high.x - 0.27f), 0.08f);
    // Water keeps its colour.
    Vec3f water{0.015f, 0.03f, 0.035f};
    TerrainTexture lake(LandClass::Water, water, grid, frame, nullptr, 3);
    EXPECT_EQ(at(lake, {150, 30}, 0.01f).x, water.x);
}

TEST(TerrainTexture, WetSiltAlongTheShore) {
    std::shared_ptr<const HeightGrid> grid = testGrid();
    LocalFrame frame{{500000, 5300000}};
    // A pond's edge running north–south at x = 50 on the flat.
    auto shore = std::make_shared<const ShoreDistance>(std::vector<std::pair<Vec2d, Vec2d>>{{{50, 0}, {50, 100}}});
    EXPECT_NEAR(shore->distance({47, 40}, 10), 3.0, 1e-12);
    EXPECT_EQ(shore->distance({20, 40}, 10), 10.0);
    Vec3f meadow{0.13f, 0.23f, 0.06f};
    TerrainTexture grass(LandClass::Grassland, meadow, grid, frame, shore, 3);
    Vec3f atTheWater = closeMean(grass, {49.5, 40}, 0.5);
    Vec3f inland = closeMean(grass, {30, 40}, 0.5);
    // Silt is brown-grey: its red above its green, where the meadow's green leads.
    EXPECT_GT(atTheWater.x, atTheWater.y * 0.95f);
    EXPECT_GT(inland.y, inland.x * 1.2f);
}

TEST(TerrainTexture, TreesKeepOffRockAndTheHeights) {
    std::shared_ptr<const HeightGrid> grid = testGrid();
    LocalFrame frame{{500000, 5300000}};
    EXPECT_TRUE(treeMayGrow(*grid, frame, {30, 30}));
    EXPECT_FALSE(treeMayGrow(*grid, frame, {150, 30}));  // 50°
    EXPECT_FALSE(treeMayGrow(*grid, frame, {30, 195}));  // 2200 m
}

}  // namespace
}  // namespace veduta
