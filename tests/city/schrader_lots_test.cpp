#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "city/building_settings.h"
#include "city/lot_checks.h"
#include "city/lot_subdivision.h"
#include "city/lot_test_blocks.h"
#include "core/hash.h"

namespace veduta {
namespace {

Block allStreets(std::vector<Vec2f> points) {
    std::vector<bool> streets(points.size(), true);
    return {std::move(points), std::move(streets), 0};
}

// The spacing of the markers with the default settings: the mean of 10 m and 22 m.
constexpr double kSpacing = 16;

double perimeter(const Block &block) {
    double length = 0;
    for (size_t e = 0; e < block.points.size(); ++e) {
        Vec2f a = block.points[e], b = block.points[(e + 1) % block.points.size()];
        length += std::hypot(double(b.x) - a.x, double(b.y) - a.y);
    }
    return length;
}

// The shortest distance between two outlines that do not cross: from a point of one to an edge
// of the other.
double gap(const std::vector<Vec2f> &a, const std::vector<Vec2f> &b) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<Vec2f> &points = pass ? b : a, &edges = pass ? a : b;
        for (Vec2f p : points) {
            for (size_t e = 0; e < edges.size(); ++e) {
                nearest = std::min(nearest, distanceToSegment(p, edges[e], edges[(e + 1) % edges.size()]));
            }
        }
    }
    return nearest;
}

// Whether the segment from p to q lies `margin` inside a street edge of the block, along it:
// the lots' fronts once they are inset.
bool alongAStreet(Vec2f p, Vec2f q, const Block &block, double margin) {
    for (size_t e = 0; e < block.points.size(); ++e) {
        if (!block.streetEdges[e]) continue;
        Vec2f s = block.points[e], t = block.points[(e + 1) % block.points.size()];
        double dx = double(t.x) - s.x, dy = double(t.y) - s.y, length = std::hypot(dx, dy);
        auto inside = [&](Vec2f x) { return (dx * (double(x.y) - s.y) - dy * (double(x.x) - s.x)) / length; };
        double middle = (dx * ((double(p.x) + q.x) / 2 - s.x) + dy * ((double(p.y) + q.y) / 2 - s.y)) / length;
        if (std::abs(inside(p) - margin) < kLengthTolerance && std::abs(inside(q) - margin) < kLengthTolerance &&
            middle >= 0 && middle <= length) {
            return true;
        }
    }
    return false;
}

size_t flaggedEdges(const Footprint &lot) {
    return size_t(std::count(lot.streetEdges.begin(), lot.streetEdges.end(), true));
}

// What every Schrader lot must be: a simple counter-clockwise polygon inside the block, at
// least RoadMargin from its outline and BuildingMargin from every other lot, with a flagged edge,
// each flagged edge along a street edge at the larger of RoadMargin and half BuildingMargin.
void expectSchraderLots(const Block &block, const std::vector<Footprint> &lots, const LotSettings &settings) {
    ExactPolygon outline = exact(block.points);
    double front = std::max(settings.roadMargin, settings.buildingMargin / 2);
    for (size_t i = 0; i < lots.size(); ++i) {
        const Footprint &lot = lots[i];
        SCOPED_TRACE(testing::Message() << "lot " << i);
        expectLotInside(lot, outline);
        if (testing::Test::HasFatalFailure()) return;
        EXPECT_GE(gap(lot.points, block.points), settings.roadMargin - kLengthTolerance);
        EXPECT_GE(flaggedEdges(lot), 1u);
        for (size_t e = 0; e < lot.edgeCount(); ++e) {
            if (!lot.streetEdges[e]) continue;
            EXPECT_TRUE(alongAStreet(lot.edgeStart(e), lot.edgeEnd(e), block, front)) << "edge " << e;
        }
        for (size_t k = i + 1; k < lots.size(); ++k) {
            EXPECT_TRUE(areDisjoint(lot.points, lots[k].points)) << "lot " << k;
            EXPECT_GE(gap(lot.points, lots[k].points), settings.buildingMargin - kLengthTolerance) << "lot " << k;
        }
    }
}

// The gap from each lot to its nearest neighbour.
std::vector<double> nearestGaps(const std::vector<Footprint> &lots) {
    std::vector<double> gaps;
    for (size_t i = 0; i < lots.size(); ++i) {
        double nearest = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < lots.size(); ++k) {
            if (k != i) nearest = std::min(nearest, gap(lots[i].points, lots[k].points));
        }
        gaps.push_back(nearest);
    }
    return gaps;
}

bool hasPointNear(const Footprint &lot, Vec2f p) {
    return std::any_of(lot.points.begin(), lot.points.end(),
                       [&](Vec2f q) { return std::hypot(q.x - p.x, q.y - p.y) < kLengthTolerance; });
}

// Block `index` of a family of jittered regular polygons, 3 to 8 points: each point's angle
// moved by up to a quarter of its sector and its radius drawn from 45–75 m, so that some are
// mildly concave; each edge a street with probability 4/5.
Block jitteredBlock(uint32_t index) {
    uint32_t draws = 0;
    auto between = [&](float lo, float hi) { return lo + (hi - lo) * bitsToUnitFloat(hashValues({index, draws++})); };
    int count = 3 + int(between(0, 6));
    std::vector<Vec2f> points;
    for (int i = 0; i < count; ++i) {
        float angle = (float(i) + between(-0.25f, 0.25f)) * 2 * kPi / float(count);
        float radius = between(45, 75);
        points.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    std::vector<bool> streets;
    for (size_t e = 0; e < points.size(); ++e) streets.push_back(between(0, 1) < 0.8f);
    return {std::move(points), std::move(streets), 0};
}

TEST(SchraderLots, ARectangleGetsALotPerMarker) {
    Block rectangle = allStreets({{0, 0}, {100, 0}, {100, 80}, {0, 80}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(rectangle, settings, 1871, 7);
    // ⌊360 m / 16 m⌋ markers, a lot between each two neighbours round the block.
    EXPECT_EQ(lots.size(), size_t(std::floor(perimeter(rectangle) / kSpacing)));
    expectSchraderLots(rectangle, lots, settings);
    // The margins are met exactly where lots face the street and their neighbours.
    for (const Footprint &lot : lots) EXPECT_NEAR(gap(lot.points, rectangle.points), 0.6, kLengthTolerance);
    for (double nearest : nearestGaps(lots)) EXPECT_NEAR(nearest, 0.6, kLengthTolerance);
    for (const Footprint &lot : lots) {
        EXPECT_EQ(lot.points.size(), 4u);
        EXPECT_GE(area(exact(lot.points)), 150);
    }
}

TEST(SchraderLots, TheCornersOfASquareAreCornerLots) {
    Block square = allStreets({{0, 0}, {64, 0}, {64, 64}, {0, 64}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(square, settings, 1, 7);
    EXPECT_EQ(lots.size(), size_t(std::floor(perimeter(square) / kSpacing)));
    expectSchraderLots(square, lots, settings);
    for (Vec2f corner : square.points) {
        SCOPED_TRACE(testing::Message() << corner.x << " " << corner.y);
        Vec2f inset{corner.x == 0 ? 0.6f : 63.4f, corner.y == 0 ? 0.6f : 63.4f};
        auto lot = std::find_if(lots.begin(), lots.end(), [&](const Footprint &l) { return hasPointNear(l, inset); });
        ASSERT_NE(lot, lots.end());
        EXPECT_EQ(flaggedEdges(*lot), 2u);
    }
}

TEST(SchraderLots, AnLShapedBlockTurnsItsReflexCorner) {
    // The reflex corner at (45, 40): the lot round it is an L itself (O4), its point there moved
    // 0.6 m off both streets.
    Block l = allStreets({{0, 0}, {90, 0}, {90, 40}, {45, 40}, {45, 90}, {0, 90}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(l, settings, 1, 7);
    EXPECT_GE(lots.size(), size_t(std::floor(perimeter(l) / kSpacing)) - 2);
    expectSchraderLots(l, lots, settings);
    auto lot = std::find_if(lots.begin(), lots.end(), [&](const Footprint &f) {
        return hasPointNear(f, {44.4f, 39.4f});
    });
    ASSERT_NE(lot, lots.end());
    EXPECT_EQ(flaggedEdges(*lot), 2u);
    EXPECT_GE(lot->points.size(), 6u);
}

TEST(SchraderLots, BackWallsRunParallelToTheStreetOfATrapezoid) {
    // The rays of the slanted sides cross the bottom's rays at depths growing along the street; a
    // lot between two rays of one edge still gets a back wall parallel to it (O3).
    Block trapezoid = allStreets({{0, 0}, {120, 0}, {90, 50}, {20, 50}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(trapezoid, settings, 1, 7);
    expectSchraderLots(trapezoid, lots, settings);
    size_t along = 0;
    for (const Footprint &lot : lots) {
        if (flaggedEdges(lot) != 1 || lot.points.size() != 4) continue;
        ++along;
        size_t street =
            size_t(std::find(lot.streetEdges.begin(), lot.streetEdges.end(), true) - lot.streetEdges.begin());
        size_t wall = (street + 2) % 4;
        Vec2f front = lot.edgeEnd(street) - lot.edgeStart(street), back = lot.edgeEnd(wall) - lot.edgeStart(wall);
        EXPECT_NEAR((front.x * back.y - front.y * back.x) / (lot.edgeLength(street) * lot.edgeLength(wall)), 0, 1e-5);
    }
    EXPECT_GE(along, 6u);
}

TEST(SchraderLots, ALongThinBlockGetsTwoRowsBackToBack) {
    // 30 m deep: one marker in the middle of each short side, whose rays meet the long sides'.
    Block thin = allStreets({{0, 0}, {200, 0}, {200, 30}, {0, 30}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(thin, settings, 1, 7);
    expectSchraderLots(thin, lots, settings);
    size_t below = 0, above = 0;
    for (const Footprint &lot : lots) {
        auto [low, high] =
            std::minmax_element(lot.points.begin(), lot.points.end(), [](Vec2f a, Vec2f b) { return a.y < b.y; });
        // Each row reaches the middle, where the short sides' rays meet, less half the margin.
        below += std::abs(low->y - 0.6f) < kLengthTolerance && std::abs(high->y - 14.7f) < kLengthTolerance;
        above += std::abs(low->y - 15.3f) < kLengthTolerance && std::abs(high->y - 29.4f) < kLengthTolerance;
    }
    EXPECT_EQ(below + above, lots.size());
    EXPECT_GE(below, 10u);
    EXPECT_GE(above, 10u);
}

TEST(SchraderLots, RaysFacingEachOtherMeetHalfway) {
    // The pointed ends' rays cross no ray of the long sides in the middle, whose rays run along
    // one line each with one of the other side (M2): the lots there meet at the block's middle.
    Block hexagon = allStreets({{0, 15}, {20, 0}, {180, 0}, {200, 15}, {180, 30}, {20, 30}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(hexagon, settings, 1, 7);
    expectSchraderLots(hexagon, lots, settings);
    size_t middle = 0;
    for (const Footprint &lot : lots) {
        auto [left, right] =
            std::minmax_element(lot.points.begin(), lot.points.end(), [](Vec2f a, Vec2f b) { return a.x < b.x; });
        if (left->x < 40 || right->x > 160) continue;
        ++middle;
        auto [low, high] =
            std::minmax_element(lot.points.begin(), lot.points.end(), [](Vec2f a, Vec2f b) { return a.y < b.y; });
        bool below = std::abs(low->y - 0.6f) < kLengthTolerance && std::abs(high->y - 14.7f) < kLengthTolerance;
        bool above = std::abs(low->y - 15.3f) < kLengthTolerance && std::abs(high->y - 29.4f) < kLengthTolerance;
        EXPECT_TRUE(below || above) << low->y << " " << high->y;
    }
    EXPECT_GE(middle, 14u);
}

TEST(SchraderLots, ATriangleGetsLotsIntoItsCorners) {
    Block triangle = allStreets({{0, 0}, {90, 0}, {45, 78}});
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(triangle, settings, 1, 7);
    EXPECT_GE(lots.size(), 6u);
    expectSchraderLots(triangle, lots, settings);
    size_t corners = 0;
    for (const Footprint &lot : lots) corners += flaggedEdges(lot) == 2;
    EXPECT_EQ(corners, 3u);
}

TEST(SchraderLots, TheMarginsAreSettings) {
    Block rectangle = allStreets({{0, 0}, {100, 0}, {100, 80}, {0, 80}});
    LotSettings settings;
    settings.roadMargin = 1.5f;
    settings.buildingMargin = 2;
    std::vector<Footprint> lots = schraderLots(rectangle, settings, 1, 7);
    EXPECT_EQ(lots.size(), size_t(std::floor(perimeter(rectangle) / kSpacing)));
    expectSchraderLots(rectangle, lots, settings);
    for (const Footprint &lot : lots) EXPECT_NEAR(gap(lot.points, rectangle.points), 1.5, kLengthTolerance);
    for (double nearest : nearestGaps(lots)) EXPECT_NEAR(nearest, 2, kLengthTolerance);
}

TEST(SchraderLots, RandomBlocksKeepTheMarginsAndApart) {
    size_t withLots = 0;
    for (uint32_t index = 0; index < 200; ++index) {
        Block block = jitteredBlock(index);
        SCOPED_TRACE(testing::Message() << "block " << index);
        ASSERT_TRUE(isSimplePolygon(block.points) && isCounterClockwise(block.points));
        std::vector<Footprint> lots = schraderLots(block, LotSettings{}, 3, index);
        expectSchraderLots(block, lots, LotSettings{});
        withLots += !lots.empty();
    }
    EXPECT_GT(withLots, 190u);
}

TEST(SchraderLots, WithoutMarginsLotsReachTheStreet) {
    // The thesis' lots before the inset: valid lots in the sense of every other algorithm.
    expectRandomBlocksGiveValidLots([](const Block &block, const LotSettings &settings, uint32_t seed, uint32_t id) {
        LotSettings touching = settings;
        touching.roadMargin = touching.buildingMargin = 0;
        return schraderLots(block, touching, seed, id);
    });
}

TEST(SchraderLots, EdgesWithoutStreetGetNoLots) {
    // One street: its lots, and the corner lots beside it, reach back to where rays from the
    // other edges cross theirs; no lot fronts the other edges alone.
    Block oneStreet{{{0, 0}, {70, 0}, {70, 50}, {0, 50}}, {true, false, false, false}, 0};
    LotSettings settings;
    std::vector<Footprint> lots = schraderLots(oneStreet, settings, 5, 3);
    EXPECT_GE(lots.size(), 4u);
    expectSchraderLots(oneStreet, lots, settings);
    for (const Footprint &lot : lots) {
        auto low = std::min_element(lot.points.begin(), lot.points.end(), [](Vec2f a, Vec2f b) { return a.y < b.y; });
        EXPECT_NEAR(low->y, 0.6, kLengthTolerance);
    }
    Block inner{{{0, 0}, {60, 0}, {60, 50}, {0, 50}}, {false, false, false, false}, 0};
    EXPECT_TRUE(schraderLots(inner, settings, 1, 1).empty());
}

TEST(SchraderLots, SameInputsGiveTheSameLots) {
    for (const NamedBlock &named : shapeBlocks()) {
        SCOPED_TRACE(named.name);
        LotSettings settings;
        std::vector<Footprint> lots = schraderLots(named.block, settings, 5, 3);
        EXPECT_FALSE(lots.empty());
        EXPECT_TRUE(sameLots(lots, schraderLots(named.block, settings, 5, 3)));
        // No choice is random but HousingDensity's.
        EXPECT_TRUE(sameLots(lots, schraderLots(named.block, settings, 6, 4)));
    }
    LotSettings half;
    half.housingDensity = 0.5f;
    const Block &rectangle = shapeBlocks()[0].block;
    EXPECT_TRUE(sameLots(schraderLots(rectangle, half, 5, 3), schraderLots(rectangle, half, 5, 3)));
    EXPECT_FALSE(sameLots(schraderLots(rectangle, half, 5, 3), schraderLots(rectangle, half, 6, 3)));
}

TEST(SchraderLots, TheSettingsAreReadFromTheStack) {
    SettingsMap block{{"LotSubdivision", {"schrader", std::nullopt, {"city.xml", 2, 3}}},
                      {"RoadMargin", {"1.25", 1.25f, {"city.xml", 3, 3}}},
                      {"BuildingMargin", {"0", 0.0f, {"city.xml", 4, 3}}}};
    LotSettings settings = lotSettingsFrom(SettingsStack({&block}));
    EXPECT_EQ(settings.algorithm, LotSubdivision::Schrader);
    EXPECT_EQ(settings.roadMargin, 1.25f);
    EXPECT_EQ(settings.buildingMargin, 0);
    EXPECT_EQ(lotSettingsFrom(SettingsStack()).roadMargin, 0.6f);
    EXPECT_EQ(lotSettingsFrom(SettingsStack()).buildingMargin, 0.6f);
    const Block &rectangle = shapeBlocks()[0].block;
    EXPECT_TRUE(sameLots(subdivideBlock(rectangle, settings, 5, 3), schraderLots(rectangle, settings, 5, 3)));
}

TEST(SchraderLots, BadSettingsAreRefused) {
    SettingsMap negative{{"RoadMargin", {"-0.5", -0.5f, {"city.xml", 9, 1}}}};
    std::string message = errorOf([&] { lotSettingsFrom(SettingsStack({&negative})); });
    EXPECT_EQ(message.rfind("city.xml:9:1: RoadMargin", 0), 0u) << message;
    SettingsMap endless{{"BuildingMargin", {"inf", std::numeric_limits<float>::infinity(), {"city.xml", 5, 2}}}};
    message = errorOf([&] { lotSettingsFrom(SettingsStack({&endless})); });
    EXPECT_EQ(message.rfind("city.xml:5:2: BuildingMargin", 0), 0u) << message;
    LotSettings nan;
    nan.buildingMargin = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(schraderLots(shapeBlocks()[0].block, nan, 1, 1), LotError);
    SettingsMap misspelt{{"LotSubdivision", {"Schrader", std::nullopt, {"city.xml", 6, 7}}}};
    message = errorOf([&] { lotSettingsFrom(SettingsStack({&misspelt})); });
    EXPECT_EQ(message.rfind("city.xml:6:7: LotSubdivision", 0), 0u) << message;
    EXPECT_NE(message.find("schrader"), std::string::npos) << message;
}

TEST(SchraderLots, LimitsAndBadBlocksStopWithAClearMessage) {
    LotSettings tiny;
    tiny.minBuildingLength = 0.001f;
    tiny.maxBuildingLength = 0.002f;
    std::string message = errorOf([&] { schraderLots(shapeBlocks()[0].block, tiny, 1, 1, FileLoc{"city.xml", 3, 5}); });
    EXPECT_EQ(message.rfind("city.xml:3:5: ", 0), 0u) << message;
    EXPECT_NE(message.find("more than 10000"), std::string::npos) << message;
    Block clockwise{{{0, 0}, {0, 80}, {100, 80}, {100, 0}}, {true, true, true, true}, 0};
    EXPECT_THROW(schraderLots(clockwise, LotSettings{}, 1, 1), LotError);
    // Too short for two markers: no lot lies between rays.
    Block small = allStreets({{0, 0}, {7, 0}, {7, 7}, {0, 7}});
    EXPECT_TRUE(schraderLots(small, LotSettings{}, 1, 1).empty());
}

}  // namespace
}  // namespace veduta
