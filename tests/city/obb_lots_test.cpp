#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "city/lot_checks.h"
#include "city/lot_subdivision.h"
#include "city/lot_test_blocks.h"

namespace veduta {
namespace {

const uint32_t kSeeds[] = {1, 1871, 90210};

float extent(const Footprint &lot, float Vec2f::*axis, bool highest) {
    auto compare = [&](Vec2f a, Vec2f b) { return a.*axis < b.*axis; };
    return (highest ? *std::max_element(lot.points.begin(), lot.points.end(), compare)
                    : *std::min_element(lot.points.begin(), lot.points.end(), compare)).*
        axis;
}

TEST(LotsObb, LotsLieInsideApartFacingAStreetWithinTheAreas) {
    LotSettings settings;
    for (const NamedBlock &named : shapeBlocks()) {
        for (uint32_t seed : kSeeds) {
            SCOPED_TRACE(testing::Message() << named.name << ", seed " << seed);
            std::vector<Footprint> lots = obbLots(named.block, settings, seed, 7);
            ASSERT_FALSE(lots.empty());
            expectValidLots(named.block, lots);
            for (const Footprint &lot : lots) {
                double lotArea = area(exact(lot.points));
                EXPECT_LE(lotArea, settings.maxLotArea + kAreaTolerance);
                EXPECT_GT(lotArea, settings.minLotArea);
            }
        }
    }
}

TEST(LotsObb, CutsRunAcrossTheLongerAxis) {
    // 200 m by 20 m with its street along a long side: cutting across the length keeps every part
    // on the street, so every lot reaches from the street to the back.
    Block strip{{{0, 0}, {200, 0}, {200, 20}, {0, 20}}, {true, false, false, false}, 0};
    LotSettings settings;
    for (uint32_t seed : kSeeds) {
        std::vector<Footprint> lots = obbLots(strip, settings, seed, 2);
        ASSERT_GE(lots.size(), 7u);  // 4000 m² in lots of at most 600 m²
        for (const Footprint &lot : lots) {
            EXPECT_NEAR(extent(lot, &Vec2f::y, false), 0, kLengthTolerance);
            EXPECT_NEAR(extent(lot, &Vec2f::y, true), 20, kLengthTolerance);
        }
    }
}

TEST(LotsObb, SplitTurnsWhereAPartWouldLoseTheStreet) {
    // The street is the short west side: a cut across the length would leave the east half
    // without it, so the split turns and every lot runs the block's whole length.
    Block deep{{{0, 0}, {100, 0}, {100, 40}, {0, 40}}, {false, false, false, true}, 0};
    LotSettings settings;
    settings.minLotArea = 0;
    settings.minLotAngleDegrees = 0;
    for (uint32_t seed : kSeeds) {
        std::vector<Footprint> lots = obbLots(deep, settings, seed, 2);
        expectValidLots(deep, lots);
        double covered = 0;
        for (const Footprint &lot : lots) {
            covered += area(exact(lot.points));
            EXPECT_NEAR(extent(lot, &Vec2f::x, false), 0, kLengthTolerance);
            EXPECT_NEAR(extent(lot, &Vec2f::x, true), 100, kLengthTolerance);
        }
        EXPECT_NEAR(covered, 4000, kAreaTolerance);  // nothing dropped
    }
}

TEST(LotsObb, SameInputsGiveTheSameLotsAndTheSeedChangesThem) {
    for (const NamedBlock &named : shapeBlocks()) {
        SCOPED_TRACE(named.name);
        LotSettings settings;
        EXPECT_TRUE(sameLots(obbLots(named.block, settings, 5, 3), obbLots(named.block, settings, 5, 3)));
        EXPECT_FALSE(sameLots(obbLots(named.block, settings, 5, 3), obbLots(named.block, settings, 6, 3)));
        EXPECT_FALSE(sameLots(obbLots(named.block, settings, 5, 3), obbLots(named.block, settings, 5, 4)));
    }
}

TEST(LotsObb, LimitsAndBadBlocksStopWithAClearMessage) {
    const Block &block = shapeBlocks()[0].block;
    LotSettings deep;
    deep.maxLotArea = 1e-6f;
    std::string message = errorOf([&] { obbLots(block, deep, 1, 1, FileLoc{"city.xml", 3, 5}); });
    EXPECT_EQ(message.rfind("city.xml:3:5: ", 0), 0u) << message;
    EXPECT_NE(message.find("more than 32"), std::string::npos) << message;
    Block clockwise{{{0, 0}, {0, 80}, {100, 80}, {100, 0}}, {true, true, true, true}, 0};
    EXPECT_THROW(obbLots(clockwise, LotSettings{}, 1, 1), LotError);
    Block inner{{{0, 0}, {60, 0}, {60, 50}, {0, 50}}, {false, false, false, false}, 0};
    EXPECT_TRUE(obbLots(inner, LotSettings{}, 1, 1).empty());
}

TEST(LotsObb, RandomBlocksGiveValidLotsOrALotError) {
    expectRandomBlocksGiveValidLots([](const Block &block, const LotSettings &settings, uint32_t seed, uint32_t id) {
        return obbLots(block, settings, seed, id);
    });
}

}  // namespace
}  // namespace veduta
