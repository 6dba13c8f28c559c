#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/error.h"
#include "geo/drape_areas.h"
#include "geo/geo_test_terrain.h"
#include "geo/ribbons.h"

namespace veduta {
namespace {

using test::unitRandom;

const MapPoint kSouthWest{3392030, 5588000};
const LocalFrame kFrame{{3392100, 5588050}};

struct Terrain : test::DrapedDgm {
    Terrain(HeightGrid g, const std::vector<DrapeArea> &areas) : DrapedDgm(std::move(g), kFrame, areas) {}
};

MapPoint at(const HeightGrid &grid, double x, double y) { return {grid.west + x, grid.south + y}; }

double ribbonHeightAt(const Mesh &ribbon, size_t t, double a, double b) {
    const Vec3f &p = ribbon.positions[ribbon.indices[3 * t]], &q = ribbon.positions[ribbon.indices[3 * t + 1]];
    const Vec3f &r = ribbon.positions[ribbon.indices[3 * t + 2]];
    return (1 - a - b) * double(p.z) + a * double(q.z) + b * double(r.z);
}

TEST(Ribbons, AnEastwardSegmentHasItsLeftToTheNorth) {
    // Rilling 2006 (digest §8) test 19: l = up × d, r = d × up, each half the width.
    Terrain flat(test::flatTerrain(21, 21, 5.0, kSouthWest, 80), {});
    RibbonOptions options;
    Mesh ribbon = drapeRibbon({at(flat.grid, 12, 40), at(flat.grid, 37, 40)}, 6, flat.surface, kFrame, options);
    ASSERT_EQ(ribbon.vertexCount(), 2u * 7);  // cut at x = 15, 20, 25, 30, 35
    Vec2f start = kFrame.toLocal(at(flat.grid, 12, 40));
    EXPECT_EQ(ribbon.positions[0], Vec3f(start.x, start.y + 3, float(80 + options.lift)));
    EXPECT_EQ(ribbon.positions[1], Vec3f(start.x, start.y - 3, float(80 + options.lift)));
    for (size_t v = 0; v < ribbon.vertexCount(); ++v) {
        EXPECT_EQ(ribbon.normals[v], Vec3f(0, 0, 1));
        EXPECT_EQ(ribbon.uvs[v].x, v % 2 ? 0.3f : -0.3f);  // 3 m either side of the centre, 10 m tiles
    }
    EXPECT_FLOAT_EQ(ribbon.uvs.back().y, 2.5f);  // 25 m over 10 m tiles
}

TEST(Ribbons, FollowAnEvenSlopeAtTheLift) {
    HeightGrid grid = test::flatTerrain(41, 21, 2.0, kSouthWest, 0);
    for (int r = 0; r < grid.rows; ++r) {
        for (int c = 0; c < grid.columns; ++c) grid.node(c, r) = float(100 + 0.375 * c);  // 0.1875 per metre east
    }
    Terrain slope(grid, {});
    RibbonOptions options;
    Mesh ribbon =
        drapeRibbon({at(grid, 3.3, 20), at(grid, 40, 21), at(grid, 75.1, 18.5)}, 5, slope.surface, kFrame, options);
    for (size_t v = 0; v + 1 < ribbon.vertexCount(); v += 2) {
        // Level across a road that climbs a little sideways: at the higher side's ground.
        double high = std::max(*slope.surface.heightAt({ribbon.positions[v].x, ribbon.positions[v].y}),
                               *slope.surface.heightAt({ribbon.positions[v + 1].x, ribbon.positions[v + 1].y}));
        EXPECT_NEAR(ribbon.positions[v].z, high + options.lift, 1e-3) << v;
    }
}

TEST(Ribbons, CornersKeepTheWidthUpToTheMiterLimit) {
    Terrain flat(test::flatTerrain(21, 21, 5.0, kSouthWest, 80), {});
    RibbonOptions options;
    Mesh square = drapeRibbon({at(flat.grid, 20, 20), at(flat.grid, 50, 20), at(flat.grid, 50, 60)}, 4, flat.surface,
                              kFrame, options);
    Vec2f corner = kFrame.toLocal(at(flat.grid, 50, 20));
    bool found = false;
    for (size_t v = 0; v + 1 < square.vertexCount(); v += 2) {
        if (std::abs(square.positions[v].x - (corner.x - 2)) < 1e-4 &&
            std::abs(square.positions[v].y - (corner.y + 2)) < 1e-4) {
            found = true;  // left corner at the miter: 2·√2 from the centre
            EXPECT_NEAR(square.positions[v + 1].x, corner.x + 2, 1e-4);
            EXPECT_NEAR(square.positions[v + 1].y, corner.y - 2, 1e-4);
        }
    }
    EXPECT_TRUE(found);
    Mesh sharp = drapeRibbon({at(flat.grid, 20, 20), at(flat.grid, 80, 20), at(flat.grid, 20, 22)}, 4, flat.surface,
                             kFrame, options);
    Vec2f tip = kFrame.toLocal(at(flat.grid, 80, 20));
    bool tipFound = false;
    for (size_t v = 0; v + 1 < sharp.vertexCount(); v += 2) {
        const Vec3f &l = sharp.positions[v], &r = sharp.positions[v + 1];
        if (std::abs(0.5f * (l.x + r.x) - tip.x) > 1e-3 || std::abs(0.5f * (l.y + r.y) - tip.y) > 1e-3) continue;
        tipFound = true;
        double offset = 0.5 * std::hypot(l.x - r.x, l.y - r.y);
        EXPECT_NEAR(offset, 2.0 * options.miterLimit, 1e-3);  // clamped: unclamped it would be about 120 m
    }
    EXPECT_TRUE(tipFound);
}

// The acceptance test of issue 8: on a rough terrain (noise, a steep slope, a sharp ridge,
// a lake levelled in it), curving roads and rails, sampled densely, never lie below the
// surface. No tolerance: both heights are read in double from the float vertices, and the
// ribbons keep their lift (5–9 cm) above, far beyond the float rounding of a vertex (< 0.1 mm).
TEST(Ribbons, NeverBelowTheTerrain) {
    HeightGrid grid = test::roughTerrain(161, 161, 1.0, kSouthWest, 31);
    DrapeArea lake{{at(grid, 20, 20), at(grid, 60, 25), at(grid, 55, 50), at(grid, 25, 45)}, LandClass::Water, 0, {}};
    Terrain terrain(grid, {lake});

    struct Line {
        MapLine centre;
        double width;
        LandClass landClass;
    };
    std::vector<Line> lines;
    for (int k = 0; k < 4; ++k) {  // sinuous roads crossing the ridge
        MapLine centre;
        for (int i = 0; i <= 60; ++i) {
            double y = 5 + 150.0 * i / 60;
            centre.push_back(at(grid, 20 + 35 * k + 12 * std::sin(y / (9 + 3 * k)), y));
        }
        lines.push_back({centre, 4.0 + 1.5 * k, k % 2 ? LandClass::Rail : LandClass::Road});
    }
    MapLine arc;  // a rail bending round across the slope and through the lake
    for (int i = 0; i <= 80; ++i) {
        double angle = M_PI * i / 80;
        arc.push_back(at(grid, 80 + 65 * std::cos(angle), 30 + 60 * std::sin(angle)));
    }
    lines.push_back({arc, 3.5, LandClass::Rail});
    lines.push_back({{at(grid, 3, 80), at(grid, 157, 80)}, 6, LandClass::Road});  // on a grid line
    lines.push_back({{at(grid, 2, 2), at(grid, 158, 158)}, 5, LandClass::Path});  // along the diagonals
    lines.push_back({{at(grid, 10, 150), at(grid, 60, 70), at(grid, 65, 140), at(grid, 150, 10)}, 7, LandClass::Road});

    std::vector<Mesh> ribbons;
    size_t triangles = 0;
    for (const Line &line : lines) {
        RibbonOptions options;
        options.lift = ribbonLift(line.landClass);
        ribbons.push_back(drapeRibbon(line.centre, line.width, terrain.surface, kFrame, options));
        triangles += ribbons.back().triangleCount();
        for (size_t v = 0; v + 1 < ribbons.back().vertexCount(); v += 2) {  // level across
            ASSERT_EQ(ribbons.back().positions[v].z, ribbons.back().positions[v + 1].z);
        }
    }
    ASSERT_GT(triangles, 1000u);

    size_t samples = 0;
    double lowest = INFINITY, clearance = 0;
    for (uint32_t i = 0; samples < 100000; ++i) {
        const Mesh &ribbon = ribbons[i % ribbons.size()];
        size_t t = size_t(unitRandom(40, i) * double(ribbon.triangleCount()));
        double a = unitRandom(41, i), b = unitRandom(42, i);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Vec3f &p = ribbon.positions[ribbon.indices[3 * t]], &q = ribbon.positions[ribbon.indices[3 * t + 1]];
        const Vec3f &r = ribbon.positions[ribbon.indices[3 * t + 2]];
        Vec2d xy{(1 - a - b) * p.x + a * q.x + b * r.x, (1 - a - b) * p.y + a * q.y + b * r.y};
        std::optional<double> ground = terrain.surface.heightAt(xy);
        if (!ground) continue;
        ++samples;
        double above = ribbonHeightAt(ribbon, t, a, b) - *ground;
        ASSERT_GE(above, 0) << "ribbon " << i % ribbons.size() << " triangle " << t << " at " << xy.x << " " << xy.y;
        lowest = std::min(lowest, above), clearance += above;
    }
    EXPECT_GE(lowest, 0.05 - 1e-4);  // the lift holds
    std::cout << "mean clearance " << clearance / double(samples) << " m\n";

    // Rilling 2006 (digest §8) test 20: no DGM node under a ribbon lies above it.
    GridLines gl = gridLines(grid, kFrame);
    for (const Mesh &ribbon : ribbons) {
        for (size_t t = 0; t < ribbon.triangleCount(); ++t) {
            const Vec3f &p = ribbon.positions[ribbon.indices[3 * t]], &q = ribbon.positions[ribbon.indices[3 * t + 1]];
            const Vec3f &r = ribbon.positions[ribbon.indices[3 * t + 2]];
            double d = (double(q.x) - p.x) * (double(r.y) - p.y) - (double(q.y) - p.y) * (double(r.x) - p.x);
            if (d == 0) continue;
            int c0 = int(std::ceil(std::min({p.x, q.x, r.x}) - gl.xs[0])),
                c1 = int(std::floor(std::max({p.x, q.x, r.x}) - gl.xs[0]));
            int r0 = int(std::ceil(std::min({p.y, q.y, r.y}) - gl.ys[0])),
                r1 = int(std::floor(std::max({p.y, q.y, r.y}) - gl.ys[0]));
            for (int row = std::max(r0, 0); row <= std::min(r1, grid.rows - 1); ++row) {
                for (int col = std::max(c0, 0); col <= std::min(c1, grid.columns - 1); ++col) {
                    double x = gl.xs[size_t(col)], y = gl.ys[size_t(row)];
                    double a = ((x - p.x) * (double(r.y) - p.y) - (y - p.y) * (double(r.x) - p.x)) / d;
                    double b = ((double(q.x) - p.x) * (y - p.y) - (double(q.y) - p.y) * (x - p.x)) / d;
                    if (a < 0 || b < 0 || a + b > 1) continue;
                    double ground = *terrain.surface.heightAt({x, y});
                    ASSERT_GE(ribbonHeightAt(ribbon, t, a, b), ground) << col << " " << row;
                }
            }
        }
    }
}

TEST(Ribbons, RejectsBadInput) {
    Terrain flat(test::flatTerrain(11, 11, 5.0, kSouthWest, 80), {});
    MapLine line{at(flat.grid, 5, 5), at(flat.grid, 30, 5)};
    EXPECT_THROW(drapeRibbon(line, 0, flat.surface, kFrame, {}), InputError);
    EXPECT_THROW(drapeRibbon({at(flat.grid, 5, 5), {NAN, 0}}, 3, flat.surface, kFrame, {}), InputError);
    EXPECT_EQ(drapeRibbon({at(flat.grid, 5, 5)}, 3, flat.surface, kFrame, {}).triangleCount(), 0u);
    EXPECT_EQ(drapeRibbon({{0, 0}, {10, 0}}, 3, flat.surface, kFrame, {}).triangleCount(), 0u);  // off the terrain
    EXPECT_GT(ribbonLift(LandClass::Rail), ribbonLift(LandClass::Road));
    EXPECT_GT(ribbonLift(LandClass::Road), ribbonLift(LandClass::Path));
}

}  // namespace
}  // namespace veduta
