// The pattern rule sets shipped in rules/streets/, grown with many seeds.
#include <gtest/gtest.h>

#include "streets/grown_streets.h"

namespace veduta {
namespace {

class StreetPatterns : public testing::TestWithParam<const char *> {};

TEST_P(StreetPatterns, GrowSoundNetworksWithBlocksForEverySeed) {
    std::string rules = test::patternText(GetParam());
    ASSERT_FALSE(rules.empty());
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        SCOPED_TRACE(seed);
        SeededDraws draws(seed);
        test::GrownStreets town(rules, draws);
        EXPECT_EQ(town.grow(400).stop, GrowthStop::Exhausted);
        EXPECT_TRUE(town.growth.warnings().empty()) << town.growth.warnings().front();
        const StreetGraph &graph = town.streets.graph();
        test::expectSoundNetwork(graph);
        // Cycles, so blocks: a tree has one edge fewer than it has vertices.
        EXPECT_GT(graph.edges().size(), graph.vertices().size() + 10);
        EXPECT_GT(town.streets.counts().snapped + town.streets.counts().split, 10u);
    }
}

INSTANTIATE_TEST_SUITE_P(RuleSets, StreetPatterns, testing::Values("grid", "organic", "radial"));

}  // namespace
}  // namespace veduta
