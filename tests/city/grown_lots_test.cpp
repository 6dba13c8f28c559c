// Issue 20's properties of the lots of grown towns, for every pattern and many seeds: every lot
// inside its block and apart from the others; Schrader lots at least their margins (0.6 m) from
// the block's edge and from one another.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "city/footprint.h"
#include "city/generate_city.h"
#include "city/grown_city.h"
#include "city/lot_checks.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

// The least distance between the outlines of two polygons that do not cross.
double outlineGap(const std::vector<Vec2f> &a, const std::vector<Vec2f> &b) {
    double gap = std::numeric_limits<double>::max();
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<Vec2f> &points = pass ? b : a, &edges = pass ? a : b;
        for (Vec2f p : points)
            for (size_t i = 0; i < edges.size(); ++i)
                gap = std::min(gap, distanceToSegment(p, edges[i], edges[(i + 1) % edges.size()]));
    }
    return gap;
}

struct Case {
    const char *pattern;
    const char *lots;
};

class GrownLots : public testing::TestWithParam<Case> {};

TEST_P(GrownLots, LieInsideTheirBlocksApartFromOneAnother) {
    // The tensor field is the one pattern without a rule file (docs/tensor-streets.md).
    bool tensor = std::string(GetParam().pattern) == "tensor";
    StreetRuleSet rules;
    if (!tensor)
        rules = readStreetRuleFile(test::sourceFile(std::string("rules/streets/") + GetParam().pattern + ".txt"));
    bool schrader = std::string(GetParam().lots) == "schrader";
    size_t lots = 0;
    for (uint32_t seed = 1; seed <= 5; ++seed) {
        SCOPED_TRACE(seed);
        CityGrowth growth;
        growth.radius = 300;
        growth.seed = seed;
        std::vector<std::string> warnings;
        CityData city = tensor ? traceCity(townField(seed, growth.radius), {}, growth, warnings)
                               : growCity(rules, growth, warnings);
        city.settings["LotSubdivision"] = settingValue(GetParam().lots, {});
        ASSERT_NO_THROW(cutLots(city, {}, seed, warnings));
        for (const CityBlock &block : city.blocks) {
            ExactPolygon outline = exact(block.points);
            std::vector<ExactPolygon> pieces;
            double areas = 0;
            for (const CityLot &lot : block.lots) {
                expectLotInside({lot.points, lot.streetEdges, lot.base}, outline);
                pieces.push_back(exact(lot.points));
                areas += area(pieces.back());
                if (schrader) {
                    EXPECT_GE(outlineGap(lot.points, block.points), 0.6 - kLengthTolerance);
                }
            }
            EXPECT_NEAR(unionArea(pieces), areas, kAreaTolerance * double(pieces.size()));
            for (size_t i = 0; schrader && i < block.lots.size(); ++i) {
                for (size_t j = i + 1; j < block.lots.size(); ++j) {
                    EXPECT_GE(outlineGap(block.lots[i].points, block.lots[j].points), 0.6 - kLengthTolerance);
                }
            }
            lots += block.lots.size();
        }
    }
    EXPECT_GT(lots, 100u);
}

INSTANTIATE_TEST_SUITE_P(Patterns, GrownLots,
                         testing::Values(Case{"grid", "perimeter"}, Case{"organic", "perimeter"},
                                         Case{"radial", "perimeter"}, Case{"grid", "schrader"},
                                         Case{"organic", "schrader"}, Case{"radial", "schrader"},
                                         Case{"tensor", "perimeter"}, Case{"tensor", "schrader"}),
                         [](const testing::TestParamInfo<Case> &c) {
                             return std::string(c.param.pattern) + "_" + c.param.lots;
                         });

}  // namespace
}  // namespace veduta
