// The streets of a network by grid cell: what buildableAreas asks for the streets near a block.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "city/city_data.h"
#include "city/generate_city.h"
#include "city/grown_city.h"
#include "city/street_geometry.h"
#include "city/street_index.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

CityData grownTown(uint32_t seed) {
    CityGrowth growth;
    growth.radius = 300;
    growth.seed = seed;
    std::vector<std::string> warnings;
    return growCity(readStreetRuleFile(test::sourceFile("rules/streets/organic.txt")), growth, warnings);
}

// Every street whose widened box meets the box is among those the index gives, in order.
TEST(StreetIndex, GivesEveryStreetThatReachesABox) {
    StreetNetwork network = streetNetworkOf(grownTown(4));
    StreetIndex index(network);
    for (float x = -300; x < 300; x += 37) {
        for (float y = -300; y < 300; y += 41) {
            Vec2f low{x, y}, high{x + 30, y + 20};
            std::vector<uint32_t> near = index.near(low, high, 2.5f);
            EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
            for (uint32_t s = 0; s < network.streets.size(); ++s) {
                Vec2f a = network.nodes[network.streets[s].from], b = network.nodes[network.streets[s].to];
                float reach = network.streets[s].width / 2 + 2.5f;
                bool reaches = std::min(a.x, b.x) - reach <= high.x && std::max(a.x, b.x) + reach >= low.x &&
                    std::min(a.y, b.y) - reach <= high.y && std::max(a.y, b.y) + reach >= low.y;
                if (!reaches) continue;
                EXPECT_TRUE(std::binary_search(near.begin(), near.end(), s)) << s;
            }
        }
    }
}

// The areas a block keeps are the same, bit for bit, whether its streets come from the index or
// from measuring every street.
TEST(StreetIndex, BuildableAreasAreTheSameWithIt) {
    for (const CityData &city : {grownTown(4), readCityData(test::sourceFile("cities/gruenderzeit-district.xml"))}) {
        StreetNetwork network = streetNetworkOf(city);
        StreetIndex index(network);
        ASSERT_FALSE(city.blocks.empty());
        for (const CityBlock &block : city.blocks) {
            std::vector<BuildableArea> measured = buildableAreas(block.points, network);
            std::vector<BuildableArea> indexed = buildableAreas(block.points, network, {}, &index);
            ASSERT_EQ(measured.size(), indexed.size());
            for (size_t a = 0; a < measured.size(); ++a) {
                ASSERT_EQ(measured[a].outline.size(), indexed[a].outline.size());
                for (size_t p = 0; p < measured[a].outline.size(); ++p) {
                    EXPECT_EQ(measured[a].outline[p].x, indexed[a].outline[p].x);
                    EXPECT_EQ(measured[a].outline[p].y, indexed[a].outline[p].y);
                }
                EXPECT_EQ(measured[a].streetEdges, indexed[a].streetEdges);
            }
        }
    }
}

}  // namespace
}  // namespace veduta
