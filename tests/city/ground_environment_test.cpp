// The ground a grown town keeps to (issue 20's ?E environment on real data): slopes, water and
// forest, the edge of the DGM, and a town grown on the hillside DGM of scenes/hillside-town.xml.
#include "city/ground_environment.h"

#include <gtest/gtest.h>

#include <cmath>

#include "city/grown_city.h"
#include "geo/height_queries.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

const LocalFrame kOrigin{{0, 0}};

TEST(GroundEnvironment, AStreetStopsBeforeASlopeTooSteepButRunsAlongIt) {
    HeightGrid grid;
    grid.columns = grid.rows = 401;
    grid.west = -200, grid.south = -200, grid.spacing = 1;
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.columns; ++c) {
            double x = grid.west + c;
            grid.heights.push_back(x > 100 ? float(0.2 * (x - 100)) : 0.0f);
        }
    GroundEnvironment ground(&grid, kOrigin, {}, {0, 0});
    float east = ground.freeLength({0, 0, 0}, {1, 0, 0}, 180);
    EXPECT_LE(east, 100);
    EXPECT_GE(east, 95);                                                // within a sampling step
    EXPECT_EQ(ground.freeLength({150, -100, 0}, {0, 1, 0}, 180), 180);  // across the slope: level
    EXPECT_EQ(ground.freeLength({-150, 0, 0}, {0, 1, 0}, 100), 100);
}

TEST(GroundEnvironment, WaterAndForestStopAStreetAndSoDoesTheEdgeOfTheDgm) {
    GroundEnvironment open(nullptr, kOrigin, {{{50, -10}, {80, -10}, {80, 10}, {50, 10}}}, {0, 0});
    float toLake = open.freeLength({0, 0, 0}, {1, 0, 0}, 100);
    EXPECT_LE(toLake, 50);
    EXPECT_GE(toLake, 45);
    EXPECT_EQ(open.freeLength({0, 20, 0}, {1, 0, 0}, 100), 100);  // past it
    EXPECT_EQ(open.freeLength({60, 0, 0}, {0, 1, 0}, 100), 0);    // in it
    // The rules' frame is moved to the centre: the same street 30 m further east meets it sooner.
    GroundEnvironment moved(nullptr, kOrigin, {{{50, -10}, {80, -10}, {80, 10}, {50, 10}}}, {30, 0});
    EXPECT_LE(moved.freeLength({0, 0, 0}, {1, 0, 0}, 100), 20);

    HeightGrid small;
    small.columns = small.rows = 101;
    small.west = small.south = -50, small.spacing = 1;
    small.heights.assign(101 * 101, 7.0f);
    GroundEnvironment dgm(&small, kOrigin, {}, {0, 0});
    EXPECT_LE(dgm.freeLength({0, 0, 0}, {1, 0, 0}, 100), 50);
    EXPECT_GE(dgm.freeLength({0, 0, 0}, {1, 0, 0}, 100), 45);
    EXPECT_EQ(dgm.freeLength({60, 0, 0}, {1, 0, 0}, 10), 0);
}

TEST(GroundEnvironment, ObstaclesAreTheWaterAndForestAreas) {
    auto area = [](int type, double x) {
        AtkisObject o;
        o.type = type;
        o.geometry = AtkisGeometry::Area;
        o.areas = {{{x, 0}, {x + 10, 0}, {x + 10, 10}}};
        return o;
    };
    std::vector<AtkisObject> objects = {area(5112, 0), area(5101, 20), area(4107, 40), area(4101, 60), area(2101, 80)};
    LocalFrame frame{{10, 0}};
    std::vector<LocalPolygon> obstacles = streetObstacles(objects, frame);
    ASSERT_EQ(obstacles.size(), 3u);   // the lake, the river, the forest; not the field or the town
    EXPECT_EQ(obstacles[2][0].x, 30);  // in the local frame
}

TEST(GroundEnvironment, ExistingRoadsAreTheRoadLinesInTheWindow) {
    auto line = [](int type, std::vector<MapPoint> points) {
        AtkisObject o;
        o.type = type;
        o.geometry = AtkisGeometry::Line;
        o.lines = {std::move(points)};
        return o;
    };
    // A road leaving the window and coming back, a path, a river line.
    std::vector<AtkisObject> objects = {line(3101, {{1000, 0}, {1050, 0}, {1300, 0}, {1060, 20}, {1040, 40}}),
                                        line(3102, {{1000, 0}, {1000, 50}}), line(5101, {{1000, 0}, {1010, 50}})};
    LocalFrame frame{{900, 0}};
    std::vector<std::vector<Vec2f>> roads = existingRoads(objects, frame, {100, 0}, 100);
    ASSERT_EQ(roads.size(), 2u);  // the road's two runs inside; the path and the river are no roads
    auto points = [](const std::vector<Vec2f> &road) {
        std::vector<std::pair<float, float>> out;
        for (Vec2f p : road) out.emplace_back(p.x, p.y);
        return out;
    };
    using Points = std::vector<std::pair<float, float>>;
    // From the rules' origin at 1000 0, cut where the road crosses the window's edge (100 m out).
    EXPECT_EQ(points(roads[0]), (Points{{0, 0}, {50, 0}, {100, 0}}));
    ASSERT_EQ(roads[1].size(), 3u);
    EXPECT_NEAR(std::hypot(roads[1][0].x, roads[1][0].y), 100, 1e-3);
    EXPECT_EQ(points(roads[1]).back(), (std::pair<float, float>{40, 40}));
}

// The hillside of scenes/hillside-town.xml rises 13 % to the north. A grid grown on it in a
// window wider than the DGM keeps to the DGM, and no street climbs more than the grade allowed:
// at 12 % only the streets across the slope are built, at 15 % the grid climbs it too.
TEST(GroundEnvironment, AGridOnTheHillsideKeepsToItsGroundAndGrade) {
    LandscapeDesc land;
    land.dgm = {{test::sourceFile("data/hillside/dgm.asc"), {"dgm"}, 0}};
    Georeference georeference{25832, 500000, 5330150};
    std::vector<std::string> warnings;
    LandscapeData data = readLandscape(land, georeference, warnings);
    LocalFrame frame{{georeference.originEasting, georeference.originNorthing}};
    size_t streetsAt12 = 0;
    for (float grade : {0.12f, 0.15f}) {
        SCOPED_TRACE(grade);
        GroundEnvironment ground(&data.grid, frame, {}, {0, 0}, {grade, 5});
        CityGrowth growth;
        growth.radius = 400;
        growth.seed = 4;
        growth.environment = &ground;
        CityData city = growCity(readStreetRuleFile(test::sourceFile("rules/streets/grid.txt")), growth, warnings);
        auto heightAt = [&](const CityPoint &p) {
            return bilinearHeight(data.grid, {frame.origin.easting + p.e, frame.origin.northing + p.n});
        };
        for (const CityStreet &s : city.streets) {
            const CityPoint &a = city.points[s.start], &b = city.points[s.end];
            std::optional<double> ha = heightAt(a), hb = heightAt(b);
            ASSERT_TRUE(ha && hb) << "a street leaves the DGM at (" << b.e << ", " << b.n << ")";
            double run = std::hypot(b.e - a.e, b.n - a.n);
            EXPECT_LE(std::abs(*hb - *ha), grade * run + 1e-3) << "street " << s.id;
        }
        if (grade == 0.12f) {
            streetsAt12 = city.streets.size();
            EXPECT_GE(streetsAt12, 3u);
        } else {
            EXPECT_GT(city.streets.size(), 3 * streetsAt12);
            EXPECT_GT(city.blocks.size(), 4u);
        }
    }
}

}  // namespace
}  // namespace veduta
