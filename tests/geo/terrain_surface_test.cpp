#include <gtest/gtest.h>

#include <cmath>

#include "geo/drape_areas.h"
#include "geo/geo_test_terrain.h"
#include "geo/terrain_surface.h"

namespace veduta {
namespace {

using test::unitRandom;

const LocalFrame kFrame{{3392100, 5588050}};

struct Fixture {
    HeightGrid grid = test::roughTerrain(61, 51, 2.0, {3392030, 5588000}, 21);
    Mesh mesh = drapeAreas(grid, kFrame, {}, {}).mesh;
    TerrainSurface surface{mesh, gridLines(grid, kFrame)};
    GridLines lines = gridLines(grid, kFrame);

    Vec2d randomPoint(uint32_t seed, uint32_t i) const {
        return {lines.xs.front() + (lines.xs.back() - lines.xs.front()) * unitRandom(seed, i),
                lines.ys.front() + (lines.ys.back() - lines.ys.front()) * unitRandom(seed + 1, i)};
    }
};

// The extremes of the mesh over a convex polygon by brute force: every triangle clipped by
// the polygon (Sutherland–Hodgman), the clipped corners' heights on the triangle's plane.
std::pair<double, double> bruteForceExtremes(const Mesh &mesh, const std::vector<Vec2d> &convex) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3f &a = mesh.positions[mesh.indices[3 * t]], &b = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3f &c = mesh.positions[mesh.indices[3 * t + 2]];
        std::vector<Vec2d> piece{{a.x, a.y}, {b.x, b.y}, {c.x, c.y}};
        for (size_t i = 0; i < convex.size() && !piece.empty(); ++i) {
            Vec2d p = convex[i], q = convex[(i + 1) % convex.size()];
            auto side = [&](Vec2d x) { return (q.x - p.x) * (x.y - p.y) - (q.y - p.y) * (x.x - p.x); };
            std::vector<Vec2d> kept;
            for (size_t k = 0; k < piece.size(); ++k) {
                Vec2d u = piece[k], v = piece[(k + 1) % piece.size()];
                double su = side(u), sv = side(v);
                if (su >= 0) kept.push_back(u);
                if ((su > 0 && sv < 0) || (su < 0 && sv > 0)) {
                    double t2 = su / (su - sv);
                    kept.push_back({u.x + t2 * (v.x - u.x), u.y + t2 * (v.y - u.y)});
                }
            }
            piece = kept;
        }
        double d = (double(b.y) - c.y) * (double(a.x) - c.x) + (double(c.x) - b.x) * (double(a.y) - c.y);
        for (Vec2d p : piece) {
            double la = ((double(b.y) - c.y) * (p.x - c.x) + (double(c.x) - b.x) * (p.y - c.y)) / d;
            double lb = ((double(c.y) - a.y) * (p.x - c.x) + (double(a.x) - c.x) * (p.y - c.y)) / d;
            double h = la * a.z + lb * b.z + (1 - la - lb) * c.z;
            lo = std::min(lo, h), hi = std::max(hi, h);
        }
    }
    return {lo, hi};
}

TEST(TerrainSurface, HeightIsTheGridSurface) {
    Fixture f;
    for (uint32_t i = 0; i < 5000; ++i) {
        Vec2d p = f.randomPoint(1, i);
        std::optional<double> h = f.surface.heightAt(p);
        ASSERT_TRUE(h) << i;
        EXPECT_NEAR(*h, test::gridSurface(f.grid, kFrame.toMap({float(p.x), float(p.y)})), 2e-3) << i;
    }
    for (int c = 0; c < f.grid.columns; c += 7) {  // at nodes, exactly
        for (int r = 0; r < f.grid.rows; r += 5)
            EXPECT_EQ(*f.surface.heightAt({f.lines.xs[size_t(c)], f.lines.ys[size_t(r)]}), f.grid.node(c, r));
    }
    EXPECT_FALSE(f.surface.heightAt({f.lines.xs.front() - 1, f.lines.ys.front()}));
}

TEST(TerrainSurface, ExtremesOverConvexPolygonsMatchBruteForce) {
    Fixture f;
    for (uint32_t i = 0; i < 60; ++i) {
        // Triangles, thin and wide quads and hexagons, some on nodes and grid lines.
        Vec2d centre = f.randomPoint(5, i);
        if (i % 5 == 0) centre = {f.lines.xs[size_t(10 + i % 30)], f.lines.ys[size_t(10 + i % 20)]};
        int corners = 3 + int(i % 4);
        double rx = 0.3 + 12 * unitRandom(6, i), ry = 0.3 + 12 * unitRandom(7, i), turn = unitRandom(8, i);
        std::vector<Vec2d> polygon;
        for (int k = 0; k < corners; ++k) {
            double angle = 2 * M_PI * (turn + double(k) / corners);
            polygon.push_back({centre.x + rx * std::cos(angle), centre.y + ry * std::sin(angle)});
        }
        if (i % 2) std::reverse(polygon.begin(), polygon.end());  // either winding
        bool inside = true;
        for (Vec2d p : polygon) inside = inside && f.surface.heightAt(p).has_value();
        if (!inside) continue;
        std::vector<Vec2d> counterClockwise = polygon;
        if (i % 2) std::reverse(counterClockwise.begin(), counterClockwise.end());
        auto [lo, hi] = bruteForceExtremes(f.mesh, counterClockwise);
        EXPECT_NEAR(*f.surface.maxOver(polygon), hi, 1e-9 * std::abs(hi) + 1e-9) << i;
        EXPECT_NEAR(*f.surface.minOver(polygon), lo, 1e-9 * std::abs(lo) + 1e-9) << i;
    }
}

TEST(TerrainSurface, ExtremesOverAConcavePolygonBoundDenseSamples) {
    Fixture f;
    Vec2d o = f.randomPoint(9, 0);
    std::vector<Vec2d> polygon{
        {o.x - 20, o.y - 15}, {o.x + 20, o.y - 15}, {o.x + 20, o.y + 15}, {o.x + 3.3, o.y - 2.1}, {o.x - 20, o.y + 15}};
    for (Vec2d &p : polygon) {  // keep it on the terrain
        p.x = std::clamp(p.x, f.lines.xs.front(), f.lines.xs.back());
        p.y = std::clamp(p.y, f.lines.ys.front(), f.lines.ys.back());
    }
    double hi = *f.surface.maxOver(polygon), lo = *f.surface.minOver(polygon);
    double sampledHi = -INFINITY, sampledLo = INFINITY;
    for (uint32_t i = 0; i < 200000; ++i) {
        Vec2d p{o.x - 20 + 40 * unitRandom(10, i), o.y - 15 + 30 * unitRandom(11, i)};
        if (!test::insideRing(polygon, p)) continue;
        std::optional<double> on = f.surface.heightAt(p);
        if (!on) continue;  // the polygon may reach past the grid's edge
        double h = *on;
        sampledHi = std::max(sampledHi, h), sampledLo = std::min(sampledLo, h);
    }
    EXPECT_GE(hi, sampledHi);
    EXPECT_LE(lo, sampledLo);
    EXPECT_LT(hi - sampledHi, 0.5);  // the samples come close
    EXPECT_LT(sampledLo - lo, 0.5);
}

TEST(TerrainSurface, MaxAboveAPlaneIsTheRiseNeeded) {
    Fixture f;
    Vec2d o = f.randomPoint(12, 0);
    std::vector<Vec2d> triangle{{o.x, o.y}, {o.x + 9, o.y + 1}, {o.x + 2, o.y + 7}};
    HeightPlane plane{150, 0.5, -0.25};
    double rise = *f.surface.maxAbove(triangle, plane);
    for (uint32_t i = 0; i < 50000; ++i) {
        double a = unitRandom(13, i), b = unitRandom(14, i);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        Vec2d p{o.x + 9 * a + 2 * b, o.y + a + 7 * b};
        std::optional<double> h = f.surface.heightAt(p);
        if (!h) continue;  // the triangle may reach past the grid's edge
        ASSERT_GE(plane.at(p) + rise, *h - 1e-9) << i;
    }
}

}  // namespace
}  // namespace veduta
