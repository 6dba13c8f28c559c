#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "geo/drape_areas.h"
#include "geo/geo_test_terrain.h"
#include "geo/grid_lines.h"

namespace veduta {
namespace {

using test::unitRandom;

const MapPoint kSouthWest{3392030, 5588000};
const LocalFrame kFrame{{3392100, 5588050}};

// A star-shaped (so simple, mostly concave) ring around a centre, in map coordinates.
MapRing star(MapPoint centre, double radius, int points, uint32_t seed) {
    MapRing ring;
    for (int i = 0; i < points; ++i) {
        double angle = 2 * M_PI * i / points, r = radius * (0.45 + 0.55 * unitRandom(seed, uint32_t(i)));
        ring.push_back({centre.easting + r * std::cos(angle), centre.northing + r * std::sin(angle)});
    }
    return ring;
}

std::vector<Vec2d> localRing(const MapRing &ring) {
    std::vector<Vec2d> local;
    for (const MapPoint &p : ring) local.push_back(toLocalDouble(p, kFrame));
    return local;
}

// The area the priority rule gives the point, worked out from the outlines alone.
uint32_t expectedArea(const std::vector<DrapeArea> &areas, Vec2d p) {
    uint32_t best = kNoArea;
    for (uint32_t i = 0; i < areas.size(); ++i) {
        if (!test::insideRing(localRing(areas[i].outline), p)) continue;
        if (best == kNoArea || drapePriority(areas[i].landClass) > drapePriority(areas[best].landClass)) best = i;
    }
    return best;
}

struct GridBox {
    double x0, y0, x1, y1;
};
GridBox localBox(const HeightGrid &grid) {
    GridLines lines = gridLines(grid, kFrame);
    return {lines.xs.front(), lines.ys.front(), lines.xs.back(), lines.ys.back()};
}

void expectWatertight(const DrapedTerrain &terrain, const HeightGrid &grid) {
    GridBox box = localBox(grid);
    std::vector<std::string> defects = test::meshDefects(terrain.mesh, box.x0, box.y0, box.x1, box.y1);
    EXPECT_TRUE(defects.empty()) << defects.size() << " defects, the first: " << (defects.empty() ? "" : defects[0]);
}

// Areas of every kind of contact with the grid: free stars, a square on grid lines through
// nodes, a ring touching a line at one point, one sticking out of the grid, a thin sliver.
std::vector<DrapeArea> testAreas(const HeightGrid &grid) {
    std::vector<DrapeArea> areas;
    // Classes below the park's and the shrubs' so that those keep their whole outline.
    LandClass classes[] = {LandClass::Farmland, LandClass::Grassland, LandClass::Other, LandClass::Grassland, {}};
    for (uint32_t i = 0; i < 8; ++i) {
        MapPoint centre{grid.west + 20 + 160 * unitRandom(7, i), grid.south + 20 + 120 * unitRandom(8, i)};
        areas.push_back({star(centre, 12 + 10 * unitRandom(9, i), 24, i), classes[i % 4], i, {}});
    }
    double s = grid.spacing;
    MapPoint n = grid.nodePoint(10, 10);
    areas.push_back(
        {{n, {n.easting + 6 * s, n.northing}, {n.easting + 6 * s, n.northing + 4 * s}, {n.easting, n.northing + 4 * s}},
         LandClass::Park,
         100,
         {}});
    MapPoint m = grid.nodePoint(60, 20);  // touches row line 20 at one point from above
    areas.push_back({{{m.easting + 0.3 * s, m.northing},
                      {m.easting + 2.7 * s, m.northing + 1.5 * s},
                      {m.easting - 1.2 * s, m.northing + 2.2 * s}},
                     LandClass::Shrubs,
                     101,
                     {}});
    areas.push_back({star({grid.west, grid.south + 60}, 30, 17, 55), LandClass::Road, 102, {}});  // half outside
    areas.push_back({{{grid.west + 31.1, grid.south + 101.05},
                      {grid.west + 75.3, grid.south + 101.0501},
                      {grid.west + 53.2, grid.south + 101.07}},
                     LandClass::Other,
                     103,
                     {}});  // a sliver
    return areas;
}

TEST(GridLines, CutsASegmentWhereItCrossesTheLines) {
    // Rilling 2006 (digest §8) test 13: (3, 3) → (27, 14) with w = 10.
    GridLines lines{{0, 10, 20, 30}, {0, 10, 20}};
    std::vector<Vec2d> cut = splitAtGridLines({{3, 3}, {27, 14}}, lines, false);
    ASSERT_EQ(cut.size(), 5u);
    EXPECT_EQ(cut[1].x, 10);
    EXPECT_NEAR(cut[1].y, 6.208, 1e-3);
    EXPECT_NEAR(cut[2].x, 18.273, 1e-3);
    EXPECT_EQ(cut[2].y, 10);
    EXPECT_EQ(cut[3].x, 20);
    EXPECT_NEAR(cut[3].y, 10.792, 1e-3);
}

TEST(GridLines, EveryPieceLiesInOneCell) {
    GridLines lines;
    for (int i = 0; i <= 20; ++i) lines.xs.push_back(0.1 * i), lines.ys.push_back(0.1 * i);
    for (uint32_t i = 0; i < 2000; ++i) {
        // Half of the segments pass through a node, where rounding could misorder two cuts.
        Vec2d a{2 * unitRandom(1, i), 2 * unitRandom(2, i)};
        Vec2d b = i % 2 ? Vec2d{2 * unitRandom(3, i), 2 * unitRandom(4, i)}
                        : Vec2d{2 * lines.xs[5] - a.x, 2 * lines.ys[7] - a.y};
        std::vector<Vec2d> cut = splitAtGridLines({a, b}, lines, false);
        for (size_t k = 1; k < cut.size(); ++k) {
            Vec2d p = cut[k - 1], q = cut[k];
            bool inside = p.x >= 0 && q.x >= 0 && p.y >= 0 && q.y >= 0 && p.x <= 2 && q.x <= 2 && p.y <= 2 && q.y <= 2;
            if (!inside) continue;
            EXPECT_GE(lines.columnsHolding(std::min(p.x, q.x), std::max(p.x, q.x)).count, 1) << i;
            EXPECT_GE(lines.rowsHolding(std::min(p.y, q.y), std::max(p.y, q.y)).count, 1) << i;
        }
    }
}

TEST(DrapeAreas, FlatPlaneNormalsAreExactlyUp) {
    // Rilling 2006 (digest §8) test 17.
    HeightGrid grid = test::flatTerrain(101, 81, 2.0, kSouthWest, 123.5f);
    DrapedTerrain terrain = drapeAreas(grid, kFrame, testAreas(grid), {});
    ASSERT_GT(terrain.mesh.triangleCount(), 2u * 100 * 80);
    for (size_t v = 0; v < terrain.mesh.vertexCount(); ++v) {
        ASSERT_EQ(terrain.mesh.normals[v], Vec3f(0, 0, 1)) << v;
        ASSERT_EQ(terrain.mesh.positions[v].z, 123.5f) << v;
    }
}

TEST(DrapeAreas, IsWatertightLiesOnTheGridAndSplitsByArea) {
    HeightGrid grid = test::roughTerrain(101, 81, 2.0, kSouthWest, 3);
    std::vector<DrapeArea> areas = testAreas(grid);
    DrapedTerrain terrain = drapeAreas(grid, kFrame, areas, {});
    const Mesh &mesh = terrain.mesh;
    ASSERT_EQ(terrain.triangleArea.size(), mesh.triangleCount());
    ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
    expectWatertight(terrain, grid);

    // Heights: the grid's own surface; at nodes, the node's height exactly.
    GridLines lines = gridLines(grid, kFrame);
    size_t nodes = 0;
    for (const Vec3f &p : mesh.positions) {
        MapPoint at = kFrame.toMap({p.x, p.y});
        ASSERT_NEAR(p.z, test::gridSurface(grid, at), 2e-3) << p.x << " " << p.y;
        auto column = std::find(lines.xs.begin(), lines.xs.end(), double(p.x));
        auto row = std::find(lines.ys.begin(), lines.ys.end(), double(p.y));
        if (column != lines.xs.end() && row != lines.ys.end()) {
            ++nodes;
            ASSERT_EQ(p.z, grid.node(int(column - lines.xs.begin()), int(row - lines.ys.begin())));
        }
    }
    EXPECT_EQ(nodes, size_t(grid.columns * grid.rows));

    // Each triangle within one grid triangle (its corners on one side of its cell's
    // diagonal and inside the cell, to float rounding), and in the area the rule gives.
    double total = 0;
    std::vector<double> areaSums(areas.size(), 0);
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        double area = test::planArea(mesh, t);
        total += area;
        if (terrain.triangleArea[t] != kNoArea) areaSums[terrain.triangleArea[t]] += area;
        Vec2d centre = test::planCentroid(mesh, t);
        int c = int(std::floor((centre.x - lines.xs[0]) / grid.spacing));
        int r = int(std::floor((centre.y - lines.ys[0]) / grid.spacing));
        double side = (centre.x - lines.xs[size_t(c)]) - (centre.y - lines.ys[size_t(r)]);
        for (size_t k = 0; k < 3; ++k) {
            const Vec3f &p = mesh.positions[mesh.indices[3 * t + k]];
            double u = p.x - lines.xs[size_t(c)], v = p.y - lines.ys[size_t(r)];
            ASSERT_TRUE(u >= -1e-4 && v >= -1e-4 && u <= grid.spacing + 1e-4 && v <= grid.spacing + 1e-4) << t;
            ASSERT_GE((u - v) * (side > 0 ? 1 : -1), -1e-4) << "triangle " << t << " crosses its cell's diagonal";
        }
        if (area > 1e-3) {
            ASSERT_EQ(terrain.triangleArea[t], expectedArea(areas, centre)) << t;
        }
    }
    GridBox box = localBox(grid);
    EXPECT_NEAR(total, (box.x1 - box.x0) * (box.y1 - box.y0), 1e-6 * total);
    // Σ triangle area = polygon area (Rilling 2006 (digest §8) test 16) for the areas inside the grid that
    // nothing of a higher priority overlaps; to the float rounding of the outline's points.
    for (size_t i : {8u, 9u}) EXPECT_NEAR(areaSums[i], test::ringArea(localRing(areas[i].outline)), 1e-3) << i;
    EXPECT_GT(areaSums[11], 0);  // the sliver is there
}

TEST(DrapeAreas, OverlapsGoToTheHigherPriority) {
    HeightGrid grid = test::roughTerrain(41, 41, 5.0, kSouthWest, 4);
    auto square = [&](double x0, double y0, double size) {
        MapPoint p{grid.west + x0, grid.south + y0};
        return MapRing{
            p, {p.easting + size, p.northing}, {p.easting + size, p.northing + size}, {p.easting, p.northing + size}};
    };
    std::vector<DrapeArea> areas{{square(10.3, 10.7, 100), LandClass::Farmland, 0, {}},
                                 {square(60.1, 50.9, 100), LandClass::Forest, 1, {}},
                                 {square(30.2, 20.4, 20), LandClass::Water, 2, {}}};
    DrapedTerrain terrain = drapeAreas(grid, kFrame, areas, {});
    expectWatertight(terrain, grid);
    std::vector<double> sums(3, 0);
    for (size_t t = 0; t < terrain.mesh.triangleCount(); ++t) {
        if (terrain.triangleArea[t] != kNoArea) sums[terrain.triangleArea[t]] += test::planArea(terrain.mesh, t);
    }
    double overlap = (110.3 - 60.1) * (110.7 - 50.9);
    // To the float rounding of the corners (about 4 µm over 400 m of outline).
    EXPECT_NEAR(sums[2], 400, 2e-3);
    EXPECT_NEAR(sums[1], 10000, 2e-3);
    EXPECT_NEAR(sums[0], 10000 - overlap - 400, 2e-3);
}

TEST(DrapeAreas, WaterIsFlatAtTheLowestPointOfItsOutline) {
    HeightGrid grid = test::roughTerrain(81, 61, 2.5, kSouthWest, 5);
    DrapeArea lake{star({grid.west + 90, grid.south + 75}, 40, 31, 11), LandClass::Water, 0, {}};
    DrapeArea forest{star({grid.west + 120, grid.south + 70}, 40, 31, 12), LandClass::Forest, 1, {}};
    DrapedTerrain terrain = drapeAreas(grid, kFrame, {lake, forest}, {});
    expectWatertight(terrain, grid);
    float level = terrain.waterLevel[0];
    EXPECT_TRUE(std::isnan(terrain.waterLevel[1]));

    // The level is the lowest point along the outline: no sample lies below it, and the
    // lowest sample comes close.
    double lowest = INFINITY;
    const MapRing &ring = lake.outline;
    for (size_t i = 0; i < ring.size(); ++i) {
        const MapPoint &a = ring[i], &b = ring[(i + 1) % ring.size()];
        for (int k = 0; k <= 2000; ++k) {
            double t = k / 2000.0;
            lowest = std::min(
                lowest,
                test::gridSurface(
                    grid, {a.easting + t * (b.easting - a.easting), a.northing + t * (b.northing - a.northing)}));
        }
    }
    EXPECT_GE(lowest, level - 1e-3);
    EXPECT_NEAR(lowest, level, 0.05);

    size_t water = 0;
    for (size_t t = 0; t < terrain.mesh.triangleCount(); ++t) {
        if (terrain.triangleArea[t] != 0) continue;
        ++water;
        for (size_t k = 0; k < 3; ++k) {
            const Vec3f &p = terrain.mesh.positions[terrain.mesh.indices[3 * t + k]];
            ASSERT_EQ(p.z, level);
            ASSERT_EQ(terrain.mesh.normals[terrain.mesh.indices[3 * t + k]].z > 0, true);
        }
        ASSERT_GT(test::planArea(terrain.mesh, t), 0);
    }
    EXPECT_GT(water, 100u);
}

TEST(DrapeAreas, CellsWithoutDataAreLeftOut) {
    HeightGrid grid = test::roughTerrain(31, 31, 3.0, kSouthWest, 6);
    grid.node(10, 12) = NAN;
    std::vector<DrapeArea> areas{{star({grid.west + 30, grid.south + 36}, 15, 20, 3), LandClass::Forest, 0, {}}};
    DrapedTerrain terrain = drapeAreas(grid, kFrame, areas, {});
    GridLines lines = gridLines(grid, kFrame);
    double hole = 4 * 9.0;  // the four cells around the node
    double total = 0;
    for (size_t t = 0; t < terrain.mesh.triangleCount(); ++t) total += test::planArea(terrain.mesh, t);
    EXPECT_NEAR(total, 90.0 * 90.0 - hole, 1e-6);
    for (const Vec3f &p : terrain.mesh.positions) ASSERT_FALSE(std::isnan(p.z));
}

TEST(DrapeAreas, LandscapeUvsAreLocalMetresOverTheTile) {
    // Rilling 2006 (digest §8) test 18: one texture tile per 10 m, the same across areas.
    HeightGrid grid = test::roughTerrain(31, 31, 3.0, kSouthWest, 7);
    DrapedTerrain terrain = drapeAreas(grid, kFrame, testAreas(grid), {});
    for (size_t v = 0; v < terrain.mesh.vertexCount(); ++v) {
        const Vec3f &p = terrain.mesh.positions[v];
        ASSERT_NEAR(terrain.mesh.uvs[v].x, p.x / 10, 1e-5);
        ASSERT_NEAR(terrain.mesh.uvs[v].y, p.y / 10, 1e-5);
    }
    DrapeOptions options;
    options.textureTile = 0;
    EXPECT_THROW(drapeAreas(grid, kFrame, {}, options), InputError);
}

TEST(DrapeAreas, RejectsBrokenOutlines) {
    HeightGrid grid = test::flatTerrain(5, 5, 1.0, kSouthWest, 0);
    MapPoint p = grid.nodePoint(1, 1);
    EXPECT_THROW(drapeAreas(grid, kFrame, {{{p, p, {p.easting + 1, p.northing}}, LandClass::Forest, 0, {}}}, {}),
                 InputError);
    EXPECT_THROW(drapeAreas(grid, kFrame, {{{p, {NAN, 1}, {p.easting + 1, p.northing}}, LandClass::Forest, 0, {}}}, {}),
                 InputError);
}

}  // namespace
}  // namespace veduta
