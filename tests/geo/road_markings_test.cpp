// Road styles by class and their markings on draped ribbons (issue 23): every mark on the
// ribbon's surface within 2 cm, the centre line within 1 cm of the ribbon's centre, dashes
// as long as the rank's, and stop lines and opened edge lines at a T-junction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geo/drape_areas.h"
#include "geo/geo_test_terrain.h"
#include "geo/ribbons.h"
#include "geo/road_markings.h"
#include "geo/road_style.h"

namespace veduta {
namespace {

const MapPoint kSouthWest{3392030, 5588000};
const LocalFrame kFrame{{3392100, 5588050}};

struct Terrain : test::DrapedDgm {
    explicit Terrain(HeightGrid g) : DrapedDgm(std::move(g), kFrame) {}
};

MapPoint at(const HeightGrid &grid, double x, double y) { return {grid.west + x, grid.south + y}; }

AtkisObject road(int objectType, std::map<std::string, std::string> attributes) {
    AtkisObject o;
    o.type = objectType;
    o.geometry = AtkisGeometry::Line;
    o.attributes = std::move(attributes);
    return o;
}

// The ribbon's height under p: the highest of its triangles that hold p (in plan), written
// apart from the library; NaN where none does.
double ribbonHeight(const Mesh &ribbon, Vec2d p) {
    double height = std::numeric_limits<double>::quiet_NaN();
    for (size_t t = 0; t < ribbon.triangleCount(); ++t) {
        Vec3f a = ribbon.positions[ribbon.indices[3 * t]], b = ribbon.positions[ribbon.indices[3 * t + 1]],
              c = ribbon.positions[ribbon.indices[3 * t + 2]];
        double area = (b.x - a.x) * double(c.y - a.y) - (b.y - a.y) * double(c.x - a.x);
        if (area == 0) continue;
        double wb = ((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x)) / area;
        double wc = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / area;
        double wa = 1 - wb - wc;
        if (std::min({wa, wb, wc}) < -1e-4) continue;
        double z = wa * a.z + wb * b.z + wc * c.z;
        if (!(z <= height)) height = z;
    }
    return height;
}

// Distance in plan from p to the ribbon's centre line (the midpoints of its vertex pairs).
double distanceToCentre(const Mesh &ribbon, Vec2d p) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t v = 0; v + 3 < ribbon.vertexCount(); v += 2) {
        Vec2d a{0.5 * (ribbon.positions[v].x + ribbon.positions[v + 1].x),
                0.5 * (ribbon.positions[v].y + ribbon.positions[v + 1].y)};
        Vec2d b{0.5 * (ribbon.positions[v + 2].x + ribbon.positions[v + 3].x),
                0.5 * (ribbon.positions[v + 2].y + ribbon.positions[v + 3].y)};
        Vec2d d = b - a;
        double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
        best = std::min(best, length(a + d * t - p));
    }
    return best;
}

// The area of a convex polygon's part inside [x0, x1] × [y0, y1] (Sutherland–Hodgman).
double clippedArea(std::vector<Vec2d> polygon, double x0, double x1, double y0, double y1) {
    auto clip = [&](auto inside, auto cut) {
        std::vector<Vec2d> out;
        for (size_t i = 0; i < polygon.size(); ++i) {
            Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            if (inside(a)) out.push_back(a);
            if (inside(a) != inside(b)) out.push_back(cut(a, b));
        }
        polygon = std::move(out);
    };
    auto atX = [](double x) { return [x](Vec2d a, Vec2d b) { return a + (b - a) * ((x - a.x) / (b.x - a.x)); }; };
    auto atY = [](double y) { return [y](Vec2d a, Vec2d b) { return a + (b - a) * ((y - a.y) / (b.y - a.y)); }; };
    clip([&](Vec2d p) { return p.x >= x0; }, atX(x0));
    clip([&](Vec2d p) { return p.x <= x1; }, atX(x1));
    clip([&](Vec2d p) { return p.y >= y0; }, atY(y0));
    clip([&](Vec2d p) { return p.y <= y1; }, atY(y1));
    return std::abs(test::ringArea(polygon));
}

double planArea(const Mesh &mesh) {
    double area = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) area += test::planArea(mesh, t);
    return area;
}

TEST(RoadStyle, SwitchesWithTheRoadClass) {
    RoadStyle motorway = roadStyle(road(3101, {{"WDM", "1301"}, {"BRF", "0290"}}));
    RoadStyle federal = roadStyle(road(3101, {{"WDM", "1303"}, {"BRF", "0075"}}));
    RoadStyle town = roadStyle(road(3101, {{"WDM", "1307"}, {"BRF", "0060"}, {"OFM", "Pflaster"}}));
    RoadStyle lane = roadStyle(road(3101, {{"WDM", "1307"}, {"BRF", "0045"}}));
    RoadStyle path = roadStyle(road(3102, {}));
    RoadStyle rail = roadStyle(road(3201, {}));

    EXPECT_EQ(motorway.rank, RoadRank::Motorway);
    EXPECT_EQ(federal.rank, RoadRank::Federal);
    EXPECT_EQ(town.rank, RoadRank::Municipal);
    EXPECT_EQ(path.rank, RoadRank::Path);
    EXPECT_EQ(rail.rank, RoadRank::Rail);

    EXPECT_EQ(motorway.pavement, Pavement::Asphalt);
    EXPECT_EQ(town.pavement, Pavement::Cobbles);
    EXPECT_EQ(path.pavement, Pavement::Gravel);
    EXPECT_EQ(rail.pavement, Pavement::Ballast);

    // A 29 m motorway: six lanes, median lines, lane lines 6 m / 12 m, edge lines 0.30 m.
    EXPECT_EQ(motorway.lanes, 6);
    EXPECT_EQ(motorway.lines.size(), 2u + 2u * (1 + 2));
    double widest = 0;
    for (const MarkingLine &l : motorway.lines) widest = std::max(widest, l.width);
    EXPECT_EQ(widest, 0.30);
    EXPECT_EQ(motorway.stopLineWidth, 0);
    // The open road: a dashed centre line 6 m / 12 m and two solid edge lines.
    ASSERT_EQ(federal.lines.size(), 3u);
    EXPECT_EQ(federal.lines[0].offset, 0);
    EXPECT_EQ(federal.lines[0].dash, 6);
    EXPECT_EQ(federal.lines[0].gap, 12);
    EXPECT_EQ(federal.lines[1].dash, 0);
    EXPECT_NEAR(federal.lines[1].offset, 3.75 - 0.05 - 0.06, 1e-12);
    EXPECT_EQ(federal.stopLineWidth, 0.5);
    // A town street: a centre line 3 m / 6 m only; a narrow one none.
    ASSERT_EQ(town.lines.size(), 1u);
    EXPECT_EQ(town.lines[0].dash, 3);
    EXPECT_TRUE(lane.lines.empty());
    EXPECT_TRUE(path.lines.empty());
    EXPECT_TRUE(rail.lines.empty());
    // FSZ is taken when the width holds it, else the width decides.
    EXPECT_EQ(roadStyle(road(3101, {{"FSZ", "4"}, {"BRF", "0140"}})).lanes, 4);
    EXPECT_EQ(roadStyle(road(3101, {{"FSZ", "4"}, {"BRF", "0060"}})).lanes, 2);
}

// A sinuous federal road over a rough terrain (a steep slope, a sharp ridge, noise at every
// node): every vertex and every triangle's centroid of its marks lies on the ribbon, above it
// by the lift, within 2 cm; the centre line's middle within 1 cm of the ribbon's centre.
TEST(RoadMarkings, FollowTheRibbonWithin1cmAcrossAndLieOnItWithin2cm) {
    Terrain terrain(test::roughTerrain(161, 161, 1.0, kSouthWest, 31));
    MapLine centre;
    for (int i = 0; i <= 60; ++i) {
        double y = 5 + 150.0 * i / 60;
        centre.push_back(at(terrain.grid, 80 + 15 * std::sin(y / 20), y));
    }
    RoadStyle style = roadStyle(road(3101, {{"WDM", "1303"}, {"BRF", "0075"}}));
    RibbonOptions ribbonOptions;
    Mesh ribbon = drapeRibbon(centre, style.width, terrain.surface, kFrame, ribbonOptions);
    MarkingOptions options;
    MarkedRoad marked{style, &ribbon};
    Mesh marks = roadMarkings({&marked, 1}, options);
    ASSERT_GT(marks.triangleCount(), 100u);

    double worstAbove = -1e30, worstBelow = 1e30;
    auto check = [&](Vec3f p) {
        double below = ribbonHeight(ribbon, {p.x, p.y});
        ASSERT_FALSE(std::isnan(below)) << p.x << " " << p.y;
        double gap = p.z - below;
        worstAbove = std::max(worstAbove, gap);
        worstBelow = std::min(worstBelow, gap);
    };
    for (const Vec3f &p : marks.positions) check(p);
    for (size_t t = 0; t < marks.triangleCount(); ++t) {
        Vec3f a = marks.positions[marks.indices[3 * t]], b = marks.positions[marks.indices[3 * t + 1]],
              c = marks.positions[marks.indices[3 * t + 2]];
        check((a + b + c) * (1.0f / 3));
        check((a + b) * 0.5f);
    }
    std::printf("marks above the ribbon: %.4f to %.4f m (lift %.2f m)\n", worstBelow, worstAbove, options.lift);
    EXPECT_LE(worstAbove, 0.02);
    EXPECT_GE(worstBelow, -0.02);
    EXPECT_GT(worstBelow, 0.0);  // never into the ribbon

    // The centre line alone: the middle of each of its cross-sections on the ribbon's centre.
    RoadStyle centreOnly = style;
    centreOnly.lines = {style.lines[0]};
    MarkedRoad centreMarked{centreOnly, &ribbon};
    Mesh centreLine = roadMarkings({&centreMarked, 1}, options);
    ASSERT_GT(centreLine.vertexCount(), 20u);
    double worst = 0;
    for (size_t v = 0; v + 1 < centreLine.vertexCount(); v += 2) {
        Vec3f a = centreLine.positions[v], b = centreLine.positions[v + 1];
        worst = std::max(worst, distanceToCentre(ribbon, {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}));
        EXPECT_NEAR(std::hypot(a.x - b.x, a.y - b.y), 0.12, 0.01);
    }
    std::printf("centre line off the ribbon's centre by at most %.4f m\n", worst);
    EXPECT_LE(worst, 0.01);
}

TEST(RoadMarkings, DashesHaveTheLengthsOfTheRank) {
    Terrain flat(test::flatTerrain(31, 11, 5.0, kSouthWest, 50));
    Mesh ribbon = drapeRibbon({at(flat.grid, 20, 25), at(flat.grid, 120, 25)}, 7.5, flat.surface, kFrame, {});
    auto areaOf = [&](const RoadStyle &style) {
        MarkedRoad marked{style, &ribbon};
        return planArea(roadMarkings({&marked, 1}, {}));
    };
    RoadStyle federal = roadStyle(road(3101, {{"WDM", "1303"}, {"BRF", "0075"}}));
    // 100 m: dashes of 6 m every 18 m (six of them) and two edge lines all along.
    EXPECT_NEAR(areaOf(federal), 6 * 6 * 0.12 + 2 * 100 * 0.12, 1e-3);
    RoadStyle town = roadStyle(road(3101, {{"WDM", "1307"}, {"BRF", "0075"}}));
    // Dashes of 3 m every 9 m: eleven whole ones (from 0 to 90 m) and one of 1 m.
    EXPECT_NEAR(areaOf(town), (11 * 3 + 1) * 0.12, 1e-3);
}

// A town street ends on a federal road's side: its lines stop 1 m short of the federal
// road's carriageway, a stop line crosses its arriving lane, and the federal road's edge line
// on that side is opened where it joins; the other edge line runs through.
TEST(RoadMarkings, StopLineAndOpenedEdgeLineAtATJunction) {
    Terrain flat(test::flatTerrain(31, 21, 5.0, kSouthWest, 50));
    Mesh main = drapeRibbon({at(flat.grid, 10, 30), at(flat.grid, 140, 30)}, 7.0, flat.surface, kFrame, {});
    Mesh side = drapeRibbon({at(flat.grid, 75, 95), at(flat.grid, 75, 30)}, 6.0, flat.surface, kFrame, {});
    MarkedRoad roads[] = {{roadStyle(road(3101, {{"WDM", "1303"}, {"BRF", "0070"}})), &main},
                          {roadStyle(road(3101, {{"WDM", "1307"}, {"BRF", "0060"}})), &side}};
    Mesh marks = roadMarkings(roads, {});
    Vec2f junction = kFrame.toLocal(at(flat.grid, 75, 30));
    auto areaIn = [&](double x0, double x1, double y0, double y1) {
        double area = 0;
        for (size_t t = 0; t < marks.triangleCount(); ++t) {
            std::vector<Vec2d> polygon;
            for (int k = 0; k < 3; ++k) {
                Vec3f p = marks.positions[marks.indices[3 * t + k]];
                polygon.push_back({p.x - junction.x, p.y - junction.y});
            }
            area += clippedArea(polygon, x0, x1, y0, y1);
        }
        return area;
    };
    // Nothing of the side street between the federal road's edge (3.5 m) and 4.5 m.
    EXPECT_EQ(areaIn(-3, 3, 3.6, 4.5), 0);
    // The stop line: 0.5 m deep from 4.5 m, across the arriving lane (heading south: to the
    // west of the centre), from the centre line's edge to the edge.
    EXPECT_NEAR(areaIn(-3, 0, 4.5, 5.0), 0.5 * (3 - 0.05 - 0.06), 1e-3);
    EXPECT_EQ(areaIn(0.01, 3, 4.5, 5.0), 0);
    // The federal road's north edge line is open for the side street's width and 1 m more
    // each way; the south one is not.
    EXPECT_EQ(areaIn(-4, 4, 3.0, 3.5), 0);
    EXPECT_NEAR(areaIn(-4, 4, -3.5, -3.0), 8 * 0.12, 1e-3);
    EXPECT_GT(areaIn(-6, -4.01, 3.0, 3.5), 0);
}

}  // namespace
}  // namespace veduta
