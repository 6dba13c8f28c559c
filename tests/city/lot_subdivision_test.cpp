#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/create_offset_polygons_2.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "city/building_settings.h"
#include "city/lot_checks.h"
#include "city/lot_subdivision.h"

namespace veduta {
namespace {

const uint32_t kSeeds[] = {1, 1871, 90210};

struct NamedBlock {
    const char *name;
    Block block;
};

const std::vector<NamedBlock> &testBlocks() {
    static const std::vector<NamedBlock> blocks{
        {"rectangle", {{{0, 0}, {100, 0}, {100, 80}, {0, 80}}, {true, true, true, true}, 0}},
        {"L", {{{0, 0}, {90, 0}, {90, 40}, {45, 40}, {45, 90}, {0, 90}}, std::vector<bool>(6, true), 0}},
        {"trapezoid", {{{0, 0}, {110, 0}, {85, 70}, {15, 70}}, {true, true, true, true}, 0}},
        {"one street", {{{0, 0}, {70, 0}, {70, 50}, {0, 50}}, {true, false, false, false}, 0}},
    };
    return blocks;
}

// The block's inset by `depth` from CGAL's straight skeleton: the courtyard, computed apart from
// the code under test.
std::vector<ExactPolygon> courtyard(const Block &block, float depth) {
    using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
    CGAL::Polygon_2<Inexact> outline;
    for (Vec2f p : block.points) outline.push_back(Inexact::Point_2(p.x, p.y));
    std::vector<ExactPolygon> insets;
    for (const auto &inset : CGAL::create_interior_skeleton_and_offset_polygons_2(double(depth), outline)) {
        ExactPolygon polygon;
        for (const Inexact::Point_2 &p : inset->vertices()) polygon.push_back(ExactKernel::Point_2(p.x(), p.y()));
        insets.push_back(polygon);
    }
    return insets;
}

double distanceToOutline(Vec2f p, const Block &block) {
    double nearest = INFINITY;
    for (size_t e = 0; e < block.points.size(); ++e) {
        nearest = std::min(nearest, distanceToSegment(p, block.points[e], block.points[(e + 1) % block.points.size()]));
    }
    return nearest;
}

// A lot between two cuts on one street edge, away from the block's corners: not a corner lot,
// nor the lot that took up an edge's remainder.
bool isMidEdgeLot(const Footprint &lot, const Block &block) {
    if (lot.points.size() != 4 || std::count(lot.streetEdges.begin(), lot.streetEdges.end(), true) != 1) return false;
    for (Vec2f p : lot.points) {
        if (nearBlockPoint(p, block)) return false;
    }
    return true;
}

TEST(Lots, PerimeterLotsTileTheRingAlongTheStreets) {
    LotSettings settings;
    for (const NamedBlock &named : testBlocks()) {
        std::vector<ExactPolygon> yard = courtyard(named.block, settings.minBuildingDepth);
        ASSERT_EQ(yard.size(), 1u) << named.name;
        for (uint32_t seed : kSeeds) {
            SCOPED_TRACE(testing::Message() << named.name << ", seed " << seed);
            std::vector<Footprint> lots = perimeterLots(named.block, settings, seed, 7);
            ASSERT_FALSE(lots.empty());
            expectValidLots(named.block, lots);
            size_t midEdge = 0;
            for (const Footprint &lot : lots) {
                EXPECT_LT(intersectionArea(exact(lot.points), yard[0]), kAreaTolerance);
                for (Vec2f p : lot.points) {
                    // Points off the outline are on the courtyard side.
                    double depth = distanceToOutline(p, named.block);
                    if (depth > kLengthTolerance) {
                        EXPECT_GE(depth, settings.minBuildingDepth - kLengthTolerance);
                    }
                }
                if (!isMidEdgeLot(lot, named.block)) continue;
                ++midEdge;
                EXPECT_GE(frontage(lot), settings.minBuildingLength - kLengthTolerance);
                EXPECT_LE(frontage(lot), settings.maxBuildingLength + kLengthTolerance);
            }
            EXPECT_GT(midEdge, 0u);
        }
    }
}

TEST(Lots, PerimeterCornerLotsTurnTheCorner) {
    const Block &rectangle = testBlocks()[0].block;
    std::vector<Footprint> lots = perimeterLots(rectangle, LotSettings{}, 1871, 7);
    size_t corners = 0;
    for (const Footprint &lot : lots) {
        if (std::count(lot.streetEdges.begin(), lot.streetEdges.end(), true) == 2) ++corners;
    }
    // The cuts move away from the inset corners rather than leave them empty (docs/lots.md).
    EXPECT_EQ(corners, 4u);
}

TEST(Lots, RecursiveLotsAreBetweenMinAndMaxArea) {
    LotSettings settings;
    for (const NamedBlock &named : testBlocks()) {
        for (uint32_t seed : kSeeds) {
            SCOPED_TRACE(testing::Message() << named.name << ", seed " << seed);
            std::vector<Footprint> lots = recursiveLots(named.block, settings, seed, 7);
            ASSERT_FALSE(lots.empty());
            expectValidLots(named.block, lots);
            for (const Footprint &lot : lots) {
                double lotArea = area(exact(lot.points));
                EXPECT_LE(lotArea, settings.maxLotArea + kAreaTolerance);
                EXPECT_GE(lotArea, settings.minLotArea);
            }
        }
    }
}

TEST(Lots, SameInputsGiveTheSameLotsAndTheSeedChangesThem) {
    const Block &block = testBlocks()[1].block;
    LotSettings settings;
    EXPECT_TRUE(sameLots(perimeterLots(block, settings, 5, 3), perimeterLots(block, settings, 5, 3)));
    EXPECT_TRUE(sameLots(recursiveLots(block, settings, 5, 3), recursiveLots(block, settings, 5, 3)));
    EXPECT_FALSE(sameLots(perimeterLots(block, settings, 5, 3), perimeterLots(block, settings, 6, 3)));
    EXPECT_FALSE(sameLots(recursiveLots(block, settings, 5, 3), recursiveLots(block, settings, 5, 4)));
}

TEST(Lots, HousingDensityKeepsAboutThatShare) {
    const Block &block = testBlocks()[0].block;
    LotSettings all, half;
    half.housingDensity = 0.5f;
    size_t total = 0, kept = 0;
    for (uint32_t blockId = 0; blockId < 30; ++blockId) {
        total += recursiveLots(block, all, 11, blockId).size();
        kept += recursiveLots(block, half, 11, blockId).size();
    }
    ASSERT_GT(total, 300u);
    EXPECT_NEAR(double(kept) / double(total), 0.5, 0.08) << kept << " of " << total;
}

TEST(Lots, FiltersDropSmallAndSharpLots) {
    Footprint square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {true, false, false, false}, 0};
    Footprint sliver{{{0, 0}, {40, 0}, {0, 10}}, {true, false, false}, 0};  // 14° at (40, 0)
    LotSettings settings;
    settings.minLotAngleDegrees = 10;
    settings.minLotArea = 50;
    EXPECT_EQ(filterLots({square, sliver}, settings, 1, 1).size(), 2u);
    settings.minLotArea = 150;  // the square has 100 m², the sliver 200 m²
    EXPECT_EQ(filterLots({square, sliver}, settings, 1, 1).size(), 1u);
    settings.minLotArea = 0;
    settings.minLotAngleDegrees = 15;
    EXPECT_EQ(filterLots({square, sliver}, settings, 1, 1).size(), 1u);
    settings.housingDensity = 0;
    EXPECT_TRUE(filterLots({square, sliver}, settings, 1, 1).empty());
}

TEST(Lots, NoLotsWithoutStreetOrRoomForTheRing) {
    Block inner{{{0, 0}, {60, 0}, {60, 50}, {0, 50}}, {false, false, false, false}, 0};
    EXPECT_TRUE(perimeterLots(inner, LotSettings{}, 1, 1).empty());
    EXPECT_TRUE(recursiveLots(inner, LotSettings{}, 1, 1).empty());
    // 20 m wide: an inset of 12 m from both sides turns round.
    Block narrow{{{0, 0}, {60, 0}, {60, 20}, {0, 20}}, {true, true, true, true}, 0};
    EXPECT_TRUE(perimeterLots(narrow, LotSettings{}, 1, 1).empty());
}

TEST(Lots, LimitsStopWithAClearMessage) {
    const Block &block = testBlocks()[0].block;
    LotSettings tiny;
    tiny.minBuildingLength = 0.01f;
    tiny.maxBuildingLength = 0.02f;
    EXPECT_THROW(perimeterLots(block, tiny, 1, 1), LotError);
    EXPECT_NE(errorOf([&] { perimeterLots(block, tiny, 1, 1); }).find("more than 10000"), std::string::npos);
    LotSettings deep;
    deep.maxLotArea = 1e-6f;
    EXPECT_THROW(recursiveLots(block, deep, 1, 1), LotError);
    std::string message = errorOf([&] { recursiveLots(block, deep, 1, 1, FileLoc{"city.xml", 3, 5}); });
    EXPECT_EQ(message.rfind("city.xml:3:5: ", 0), 0u) << message;
    EXPECT_NE(message.find("more than 32"), std::string::npos) << message;
}

TEST(Lots, BadBlocksAndSettingsAreRefused) {
    Block clockwise{{{0, 0}, {0, 80}, {100, 80}, {100, 0}}, {true, true, true, true}, 0};
    EXPECT_NE(errorOf([&] { perimeterLots(clockwise, LotSettings{}, 1, 1); }).find("clockwise"), std::string::npos);
    Block unflagged{{{0, 0}, {100, 0}, {100, 80}}, {true}, 0};
    EXPECT_THROW(recursiveLots(unflagged, LotSettings{}, 1, 1), LotError);
    LotSettings reversed;
    reversed.minBuildingLength = 30;
    EXPECT_NE(errorOf([&] { checkLotSettings(reversed); }).find("MaxBuildingLength"), std::string::npos);
}

TEST(Lots, SettingsAreReadFromTheStack) {
    SettingsMap block{{"MinBuildingLength", {"8", 8.0f, {"city.xml", 2, 3}}},
                      {"MinLotAngle", {"20", 20.0f, {"city.xml", 4, 3}}}};
    LotSettings settings = lotSettingsFrom(SettingsStack({&block}));
    EXPECT_EQ(settings.minBuildingLength, 8);
    EXPECT_EQ(settings.minLotAngleDegrees, 20);
    EXPECT_EQ(settings.maxBuildingLength, LotSettings{}.maxBuildingLength);
    SettingsMap dense{{"HousingDensity", {"1.5", 1.5f, {"city.xml", 9, 1}}}};
    std::string message = errorOf([&] { lotSettingsFrom(SettingsStack({&dense})); });
    EXPECT_EQ(message.rfind("city.xml:9:1: HousingDensity", 0), 0u) << message;
}

TEST(Lots, SubdivisionIsReadFromTheSettings) {
    EXPECT_EQ(lotSettingsFrom(SettingsStack()).algorithm, LotSubdivision::Perimeter);
    const std::pair<const char *, LotSubdivision> names[] = {{"perimeter", LotSubdivision::Perimeter},
                                                             {"recursive", LotSubdivision::Recursive},
                                                             {"obb", LotSubdivision::Obb},
                                                             {"skeleton", LotSubdivision::Skeleton}};
    for (const auto &[name, algorithm] : names) {
        SettingsMap block{{"LotSubdivision", {name, std::nullopt, {"city.xml", 2, 3}}}};
        EXPECT_EQ(lotSettingsFrom(SettingsStack({&block})).algorithm, algorithm) << name;
    }
    SettingsMap unknown{{"LotSubdivision", {"voronoi", std::nullopt, {"city.xml", 6, 7}}}};
    std::string message = errorOf([&] { lotSettingsFrom(SettingsStack({&unknown})); });
    EXPECT_EQ(message.rfind("city.xml:6:7: LotSubdivision", 0), 0u) << message;
    EXPECT_NE(message.find("'voronoi'"), std::string::npos) << message;
}

TEST(Lots, SubdivideBlockRunsTheChosenAlgorithm) {
    const Block &block = testBlocks()[1].block;
    LotSettings settings;
    EXPECT_TRUE(sameLots(subdivideBlock(block, settings, 5, 3), perimeterLots(block, settings, 5, 3)));
    settings.algorithm = LotSubdivision::Recursive;
    EXPECT_TRUE(sameLots(subdivideBlock(block, settings, 5, 3), recursiveLots(block, settings, 5, 3)));
    settings.algorithm = LotSubdivision::Obb;
    EXPECT_TRUE(sameLots(subdivideBlock(block, settings, 5, 3), obbLots(block, settings, 5, 3)));
    settings.algorithm = LotSubdivision::Skeleton;
    EXPECT_TRUE(sameLots(subdivideBlock(block, settings, 5, 3), skeletonLots(block, settings, 5, 3)));
}

TEST(Lots, PerimeterFallsBackToRecursiveWhereItGivesNoLots) {
    // 20 m wide: too narrow for a ring of 12 m deep houses round a courtyard.
    Block narrow{{{0, 0}, {60, 0}, {60, 20}, {0, 20}}, {true, true, true, true}, 0};
    std::vector<Footprint> lots = subdivideBlock(narrow, LotSettings{}, 1, 1);
    EXPECT_FALSE(lots.empty());
    EXPECT_TRUE(sameLots(lots, recursiveLots(narrow, LotSettings{}, 1, 1)));
}

}  // namespace
}  // namespace veduta
