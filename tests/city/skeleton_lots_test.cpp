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

// No filter drops a lot: what the strips give, all of it.
LotSettings unfiltered() {
    LotSettings settings;
    settings.minLotArea = 0;
    settings.minLotAngleDegrees = 0;
    return settings;
}

size_t flaggedEdges(const Footprint &lot) {
    return size_t(std::count(lot.streetEdges.begin(), lot.streetEdges.end(), true));
}

TEST(LotsSkeleton, LotsLieInsideApartFacingAStreet) {
    LotSettings settings;
    for (const NamedBlock &named : shapeBlocks()) {
        for (uint32_t seed : kSeeds) {
            SCOPED_TRACE(testing::Message() << named.name << ", seed " << seed);
            std::vector<Footprint> lots = skeletonLots(named.block, settings, seed, 7);
            ASSERT_FALSE(lots.empty());
            expectValidLots(named.block, lots);
            for (const Footprint &lot : lots) {
                EXPECT_GT(area(exact(lot.points)), settings.minLotArea);
                EXPECT_GE(frontage(lot), settings.minBuildingLength - kLengthTolerance);
            }
        }
    }
}

TEST(LotsSkeleton, StripsTileTheBlock) {
    for (const NamedBlock &named : shapeBlocks()) {
        SCOPED_TRACE(named.name);
        std::vector<Footprint> lots = skeletonLots(named.block, unfiltered(), 1871, 7);
        std::vector<ExactPolygon> polygons;
        for (const Footprint &lot : lots) polygons.push_back(exact(lot.points));
        EXPECT_NEAR(unionArea(polygons), area(exact(named.block.points)), kAreaTolerance);
    }
}

TEST(LotsSkeleton, FrontagesBetweenCornersAreDrawnFromTheRange) {
    LotSettings settings = unfiltered();
    const Block &rectangle = shapeBlocks()[0].block;
    size_t inner = 0;
    for (uint32_t seed : kSeeds) {
        for (const Footprint &lot : skeletonLots(rectangle, settings, seed, 7)) {
            if (flaggedEdges(lot) != 1) continue;
            ++inner;
            EXPECT_GE(frontage(lot), settings.minBuildingLength - kLengthTolerance);
            // The last lot of a strip takes a rest shorter than MinBuildingLength.
            EXPECT_LT(frontage(lot), settings.maxBuildingLength + settings.minBuildingLength);
        }
    }
    EXPECT_GT(inner, 6u);
}

TEST(LotsSkeleton, CornersOfTwoStreetsAreCornerLotsOfTheLongerStreet) {
    // 100 m by 80 m: the corners go to the 100 m streets, whose strips reach 40 m deep, and leave
    // the 80 m streets none of their own.
    const Block &rectangle = shapeBlocks()[0].block;
    std::vector<Footprint> lots = skeletonLots(rectangle, unfiltered(), 1871, 7);
    for (Vec2f corner : rectangle.points) {
        SCOPED_TRACE(testing::Message() << corner.x << " " << corner.y);
        auto holds = [&](const Footprint &lot) {
            return std::any_of(lot.points.begin(), lot.points.end(),
                               [&](Vec2f p) { return p.x == corner.x && p.y == corner.y; });
        };
        auto lot = std::find_if(lots.begin(), lots.end(), holds);
        ASSERT_NE(lot, lots.end());
        EXPECT_EQ(flaggedEdges(*lot), 2u);
    }
    for (const Footprint &lot : lots) {
        for (Vec2f p : lot.points) EXPECT_TRUE(std::abs(p.y - 40) < kLengthTolerance || p.y == 0 || p.y == 80);
    }
}

TEST(LotsSkeleton, EdgesWithoutStreetJoinAStreetStrip) {
    // One street: the whole block is its strip, cut into lots reaching to the back.
    const Block &oneStreet = shapeBlocks()[1].block;
    std::vector<Footprint> lots = skeletonLots(oneStreet, unfiltered(), 5, 3);
    ASSERT_GE(lots.size(), 3u);
    for (const Footprint &lot : lots) {
        auto [low, high] =
            std::minmax_element(lot.points.begin(), lot.points.end(), [](Vec2f a, Vec2f b) { return a.y < b.y; });
        EXPECT_EQ(low->y, 0);
        EXPECT_EQ(high->y, 50);
    }
    Block inner{{{0, 0}, {60, 0}, {60, 50}, {0, 50}}, {false, false, false, false}, 0};
    EXPECT_TRUE(skeletonLots(inner, LotSettings{}, 1, 1).empty());
}

TEST(LotsSkeleton, SameInputsGiveTheSameLotsAndTheSeedChangesThem) {
    for (const NamedBlock &named : shapeBlocks()) {
        SCOPED_TRACE(named.name);
        LotSettings settings;
        EXPECT_TRUE(sameLots(skeletonLots(named.block, settings, 5, 3), skeletonLots(named.block, settings, 5, 3)));
        EXPECT_FALSE(sameLots(skeletonLots(named.block, settings, 5, 3), skeletonLots(named.block, settings, 6, 3)));
        EXPECT_FALSE(sameLots(skeletonLots(named.block, settings, 5, 3), skeletonLots(named.block, settings, 5, 4)));
    }
}

TEST(LotsSkeleton, LimitsAndBadBlocksStopWithAClearMessage) {
    LotSettings tiny;
    tiny.minBuildingLength = 0.001f;
    tiny.maxBuildingLength = 0.002f;
    std::string message = errorOf([&] { skeletonLots(shapeBlocks()[0].block, tiny, 1, 1, FileLoc{"city.xml", 3, 5}); });
    EXPECT_EQ(message.rfind("city.xml:3:5: ", 0), 0u) << message;
    EXPECT_NE(message.find("more than 10000"), std::string::npos) << message;
    Block clockwise{{{0, 0}, {0, 80}, {100, 80}, {100, 0}}, {true, true, true, true}, 0};
    EXPECT_THROW(skeletonLots(clockwise, LotSettings{}, 1, 1), LotError);
}

TEST(LotsSkeleton, RandomBlocksGiveValidLotsOrALotError) {
    expectRandomBlocksGiveValidLots([](const Block &block, const LotSettings &settings, uint32_t seed, uint32_t id) {
        return skeletonLots(block, settings, seed, id);
    });
}

}  // namespace
}  // namespace veduta
