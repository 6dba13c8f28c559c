// Goitowski's futuristic cities (digest-002 §4, §10.2): upper street levels grown by the same
// rules with seeds of their own, lifts between their junctions, floating streets, crossings and
// prisms of U[7, 18] m, all closed, the same on any number of threads.
#include <gtest/gtest.h>

#include <set>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "assembly/build_scene.h"
#include "city/futuristic_city.h"
#include "city/lot_checks.h"
#include "city/prism_building.h"
#include "input_error.h"
#include "scene/scene_hash.h"
#include "scene/solid_checks.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

TEST(Lifts, JoinJunctionsThatAreEachOthersNearestWithinReach) {
    std::vector<Vec3f> lower{{0, 0, 0}, {50, 0, 0}, {100, 0, 0}};
    std::vector<Vec3f> upper{{3, 4, 40}, {52, 0, 40}, {200, 0, 40}, {101, 0, 40}, {99, 0, 40}};
    std::vector<Lift> lifts = liftsBetween(lower, upper, 15);
    ASSERT_EQ(lifts.size(), 3u);
    EXPECT_EQ(lifts[0].bottom, lower[0]);
    EXPECT_EQ(lifts[0].top, upper[0]);
    EXPECT_EQ(lifts[1].top, upper[1]);
    // (200, 0) is 100 m from its nearest; (99, 0) is not the nearest of (100, 0): (101, 0) came first.
    EXPECT_EQ(lifts[2].top, upper[3]);
    EXPECT_TRUE(liftsBetween(lower, upper, 4.9f).size() == 2u);
    EXPECT_TRUE(liftsBetween({}, upper, 15).empty());
}

TEST(UpperLevels, GrowWithTheirOwnSeedsAndCutLotsInsideTheirBlocks) {
    StreetRuleSet rules = readStreetRuleFile(test::sourceFile("rules/streets/grid.txt"));
    CityGrowth ground;
    ground.radius = 250;
    ground.seed = 5;
    std::vector<std::string> warnings;
    auto grow = [&](const CityGrowth &growth, std::vector<std::string> &found) {
        return growCity(rules, growth, found);
    };
    std::vector<UpperLevel> levels = growUpperLevels(grow, ground, 3, {}, warnings);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(levels[0].index, 1u);
    EXPECT_EQ(levels[1].index, 2u);
    EXPECT_NE(levels[0].seed, levels[1].seed);
    EXPECT_NE(levels[0].seed, ground.seed);
    EXPECT_EQ(levelSeed(5, 0), 5u);
    // One rule set, other draws: the levels are alike, not the same.
    std::vector<std::string> none;
    CityData groundCity = growCity(rules, ground, none);
    for (const UpperLevel &level : levels) {
        EXPECT_GT(level.city.streets.size(), 20u);
        bool same = level.city.points.size() == groundCity.points.size() &&
            std::equal(level.city.points.begin(), level.city.points.end(), groundCity.points.begin(),
                       [](const CityPoint &a, const CityPoint &b) { return a.e == b.e && a.n == b.n; });
        EXPECT_FALSE(same);
        size_t lots = 0;
        for (const CityBlock &block : level.city.blocks) {
            ExactPolygon outline = exact(block.points);
            for (const CityLot &lot : block.lots) {
                expectLotInside({lot.points, lot.streetEdges, lot.base}, outline);
                ++lots;
            }
        }
        EXPECT_GT(lots, 20u);
    }
}

RenderScene build(const std::string &generate) {
    std::string xml = fmt::format(
        "<scene version=\"1\"><generate streets=\"../rules/streets/grid.txt\" "
        "rules=\"../rules/gruenderzeit/FacadeStructure.xml\" {}/></scene>",
        generate);
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")));
}

TEST(FuturisticCity, FloatsPrismsOfSevenToEighteenMetresOnEachLevel) {
    RenderScene city = build("radius=\"200\" seed=\"7\" levels=\"3\" level_spacing=\"35\"");
    std::set<float> bases;
    std::set<uint32_t> floating;
    for (const BuildingRecord &b : city.buildings) {
        if (b.base < 1) continue;  // the ground's, on the ground
        bases.insert(b.base);
        floating.insert(b.id);
        EXPECT_GE(b.eaves - b.base, kPrismMinHeight) << b.id;
        EXPECT_LE(b.eaves - b.base, kPrismMaxHeight) << b.id;
        EXPECT_EQ(b.roof, "flat");
    }
    EXPECT_EQ(bases, (std::set<float>{35, 70}));
    EXPECT_GT(floating.size(), 40u);
    size_t closed = 0;
    bool structure = false;
    for (const BakedMesh &m : city.meshes) {
        if (floating.count(m.buildingId)) {
            EXPECT_TRUE(isWatertight(m.mesh)) << m.buildingId;
            ++closed;
        }
        float top = 0;
        for (const Vec3f &p : m.mesh.positions) top = std::max(top, p.z);
        if (m.buildingId == 0 && top > 60) {  // the upper levels' streets, crossings and lifts
            structure = true;
            EXPECT_TRUE(isWatertight(m.mesh));
            // Lifts: platforms and rails between the levels, away from the street tops.
            size_t between = 0;
            for (const Vec3f &p : m.mesh.positions) between += p.z > 1 && p.z < 33;
            EXPECT_GT(between, 0u);
        }
    }
    EXPECT_EQ(closed, floating.size());
    EXPECT_TRUE(structure);
}

TEST(FuturisticCity, IsTheSameOnAnyNumberOfThreads) {
    auto builtOn = [](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return build("radius=\"180\" seed=\"2\" levels=\"2\"");
    };
    RenderScene one = builtOn(1), four = builtOn(4);
    EXPECT_EQ(one.buildings.size(), four.buildings.size());
    EXPECT_EQ(sceneHash(one), sceneHash(four));
}

TEST(FuturisticCity, LevelsTooCloseForItsPrismsAreAnError) {
    EXPECT_EQ(test::inputErrorOf([] { build("radius=\"100\" levels=\"2\" level_spacing=\"15\""); }),
              "test.xml:1:155: attribute 'level_spacing' is 15, outside [19, 1000]");
}

}  // namespace
}  // namespace veduta
