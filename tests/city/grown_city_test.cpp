#include "city/grown_city.h"

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "city/generate_city.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

StreetRuleSet pattern(const std::string &name) {
    return readStreetRuleFile(test::sourceFile("rules/streets/" + name + ".txt"));
}

double signedArea(const std::vector<Vec2f> &points) {
    double twice = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec2f &p = points[i], &q = points[(i + 1) % points.size()];
        twice += double(p.x) * q.y - double(q.x) * p.y;
    }
    return twice / 2;
}

CityGrowth window(float radius, uint32_t seed) {
    CityGrowth growth;
    growth.radius = radius;
    growth.seed = seed;
    return growth;
}

TEST(GrowCity, EveryStreetVertexIsAPointEveryEdgeAStreetEveryFaceABlock) {
    std::vector<std::string> warnings;
    CityGrowthReport report;
    CityData city = growCity(pattern("grid"), window(300, 1), warnings, &report);
    EXPECT_EQ(report.growth.stop, GrowthStop::Exhausted);
    // The root, a vertex per street as proposed and per street cut; one bent onto a vertex adds
    // none. Cutting a street makes two of it.
    const StreetCounts &made = report.streets;
    EXPECT_EQ(city.points.size(), 1 + made.proposed + made.split);
    EXPECT_EQ(city.streets.size(), made.proposed + made.snapped + 2 * made.split);
    EXPECT_GT(city.blocks.size(), 10u);
    EXPECT_EQ(report.blocks, city.blocks.size());
    for (const CityStreet &street : city.streets) {
        EXPECT_LT(street.start, city.points.size());
        EXPECT_LT(street.end, city.points.size());
    }
    for (const CityBlock &block : city.blocks) {
        EXPECT_GE(block.points.size(), 3u);
        EXPECT_GT(signedArea(block.points), 0);  // counter-clockwise
    }
}

TEST(GrowCity, TheSameSeedGrowsTheSameCity) {
    std::vector<std::string> warnings;
    CityData a = growCity(pattern("organic"), window(250, 9), warnings);
    CityData b = growCity(pattern("organic"), window(250, 9), warnings);
    ASSERT_EQ(a.blocks.size(), b.blocks.size());
    for (size_t i = 0; i < a.blocks.size(); ++i) {
        EXPECT_EQ(a.blocks[i].sourceId, b.blocks[i].sourceId);
        ASSERT_EQ(a.blocks[i].points.size(), b.blocks[i].points.size());
        for (size_t j = 0; j < a.blocks[i].points.size(); ++j) {
            EXPECT_EQ(a.blocks[i].points[j].x, b.blocks[i].points[j].x);
            EXPECT_EQ(a.blocks[i].points[j].y, b.blocks[i].points[j].y);
        }
    }
}

TEST(GrowCity, MainStreetsTakeTheMajorWidthTheOthersTheNetworks) {
    std::vector<std::string> warnings;
    CityGrowth growth = window(400, 2);
    CityGrowthReport report;
    CityData city = growCity(pattern("grid"), growth, warnings, &report);
    EXPECT_EQ(city.streetWidth, growth.hierarchy.minorWidth);
    size_t major = 0;
    for (const CityStreet &street : city.streets) {
        if (!street.width) continue;
        EXPECT_EQ(*street.width, growth.hierarchy.majorWidth);
        ++major;
    }
    EXPECT_EQ(major, report.majorStreets);
    EXPECT_GT(major, city.streets.size() / 10);
    EXPECT_LT(major, city.streets.size() / 2);
}

TEST(GrowCity, TheCentreMovesTheCity) {
    std::vector<std::string> warnings;
    CityGrowth growth = window(250, 4);
    CityData here = growCity(pattern("radial"), growth, warnings);
    growth.centre = {1200, -700};
    CityData there = growCity(pattern("radial"), growth, warnings);
    ASSERT_EQ(here.points.size(), there.points.size());
    ASSERT_EQ(here.blocks.size(), there.blocks.size());
    for (size_t i = 0; i < here.points.size(); ++i) {
        EXPECT_NEAR(there.points[i].e, here.points[i].e + 1200, 1e-3);
        EXPECT_NEAR(there.points[i].n, here.points[i].n - 700, 1e-3);
    }
    for (size_t b = 0; b < here.blocks.size(); ++b) EXPECT_EQ(there.blocks[b].sourceId, here.blocks[b].sourceId);
}

TEST(GrowCity, AGrowthStoppedByALimitSaysSo) {
    std::vector<std::string> warnings;
    CityGrowth growth = window(300, 1);
    growth.limits.maxExpansions = 5;
    growCity(pattern("grid"), growth, warnings);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings.back().find("stopped at a limit after 5 expansions"), std::string::npos) << warnings.back();
}

TEST(GrowCity, TheGrownCityIsBuiltWithLotsAndGruenderzeitBuildings) {
    std::vector<std::string> warnings;
    CityData city = growCity(pattern("grid"), window(200, 3), warnings);
    city.ruleFiles = {test::sourceFile("rules/gruenderzeit/FacadeStructure.xml")};
    RenderSceneBuilder builder;
    uint32_t buildings = generateCity(city, 3, 1, builder, warnings);
    EXPECT_GT(buildings, 20u) << fmt::format("{}", fmt::join(warnings, "\n"));
}

}  // namespace
}  // namespace veduta
