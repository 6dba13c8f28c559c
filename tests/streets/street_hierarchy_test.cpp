#include "streets/street_hierarchy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "streets/grown_streets.h"

namespace veduta {
namespace {

// A road along the x axis from 0 to 500 in edges of 100, with a side street of 50 going north
// at each inner vertex: points 0-5 on the road, 6-9 the side streets' ends.
struct RoadWithSideStreets {
    std::vector<PlanarPoint> points = {{0, 0},   {100, 0},  {200, 0},  {300, 0},  {400, 0},
                                       {500, 0}, {100, 50}, {200, 50}, {300, 50}, {400, 50}};
    std::vector<PlanarEdge> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {1, 6}, {2, 7}, {3, 8}, {4, 9}};
};

// Each edge in exactly one stroke, and each stroke a chain: consecutive edges share a point.
void expectPartition(const std::vector<Stroke> &strokes, const std::vector<PlanarEdge> &edges) {
    std::vector<int> seen(edges.size(), 0);
    for (const Stroke &stroke : strokes) {
        for (uint32_t e : stroke) ++seen[e];
        for (size_t i = 1; i < stroke.size(); ++i) {
            const PlanarEdge &a = edges[stroke[i - 1]], &b = edges[stroke[i]];
            EXPECT_TRUE(a.first == b.first || a.first == b.second || a.second == b.first || a.second == b.second)
                << "edges " << stroke[i - 1] << " and " << stroke[i] << " do not meet";
        }
    }
    for (size_t e = 0; e < edges.size(); ++e) EXPECT_EQ(seen[e], 1) << "edge " << e;
}

TEST(StreetStrokes, AStraightRoadIsOneStrokeThroughItsSideStreets) {
    RoadWithSideStreets town;
    std::vector<Stroke> strokes = strokesOf(town.points, town.edges, 30);
    expectPartition(strokes, town.edges);
    ASSERT_EQ(strokes.size(), 5u);
    EXPECT_EQ(strokes[0], (Stroke{0, 1, 2, 3, 4}));
    for (uint32_t s = 1; s < 5; ++s) EXPECT_EQ(strokes[s], Stroke{4 + s});
}

TEST(StreetStrokes, EdgesContinueOnlyWithinTheTurnThreshold) {
    // Two edges meeting at the origin, the second turning off the first's line by 40°.
    double turn = 40 * std::numbers::pi / 180;
    std::vector<PlanarPoint> points = {{-100, 0}, {0, 0}, {100 * std::cos(turn), 100 * std::sin(turn)}};
    std::vector<PlanarEdge> edges = {{0, 1}, {1, 2}};
    EXPECT_EQ(strokesOf(points, edges, 30).size(), 2u);
    EXPECT_EQ(strokesOf(points, edges, 45).size(), 1u);
}

TEST(StreetStrokes, TheStraightestPairContinuesAtACrossing) {
    // Four edges from the origin: west, east, north, and one 10° south of west. East goes on
    // straight into west rather than into the one 10° off; north goes on into neither.
    double offWest = 190 * std::numbers::pi / 180;
    std::vector<PlanarPoint> points = {
        {0, 0}, {-100, 0}, {100, 0}, {0, 100}, {100 * std::cos(offWest), 100 * std::sin(offWest)}};
    std::vector<PlanarEdge> edges = {{0, 1}, {0, 2}, {0, 3}, {0, 4}};
    std::vector<Stroke> strokes = strokesOf(points, edges, 30);
    expectPartition(strokes, edges);
    ASSERT_EQ(strokes.size(), 3u);
    EXPECT_EQ(strokes[0], (Stroke{1, 0}));  // from the east end through the crossing to the west
}

TEST(StreetStrokes, ARingOfGentleTurnsIsOneClosedStroke) {
    // A regular 12-gon turns 30° at each corner.
    std::vector<PlanarPoint> points;
    std::vector<PlanarEdge> edges;
    for (uint32_t i = 0; i < 12; ++i) {
        double a = i * std::numbers::pi / 6;
        points.push_back({100 * std::cos(a), 100 * std::sin(a)});
        edges.emplace_back(i, (i + 1) % 12);
    }
    std::vector<Stroke> strokes = strokesOf(points, edges, 31);
    expectPartition(strokes, edges);
    EXPECT_EQ(strokes.size(), 1u);
    EXPECT_EQ(strokesOf(points, edges, 29).size(), 12u);
}

TEST(StreetHierarchyClasses, TheLongestStrokeIsTheMainStreet) {
    RoadWithSideStreets town;
    std::vector<StreetClass> classes = classifyStreets(town.points, town.edges, {});
    for (uint32_t e = 0; e < 5; ++e) EXPECT_EQ(classes[e], StreetClass::Major) << e;
    for (uint32_t e = 5; e < 9; ++e) EXPECT_EQ(classes[e], StreetClass::Minor) << e;
    StreetHierarchy none;
    none.majorShare = 0;
    classes = classifyStreets(town.points, town.edges, none);
    EXPECT_EQ(std::count(classes.begin(), classes.end(), StreetClass::Major), 0);
}

class StreetHierarchyOfPatterns : public testing::TestWithParam<const char *> {};

// On grown networks: strokes partition the edges, and the main streets hold at least the share
// asked for and less than that plus the longest stroke.
TEST_P(StreetHierarchyOfPatterns, MainStreetsHoldTheirShare) {
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        SeededDraws draws(seed);
        test::GrownStreets town(test::patternText(GetParam()), draws);
        town.grow(400);
        std::vector<PlanarPoint> points;
        for (const StreetVertex &v : town.streets.graph().vertices()) points.push_back({v.position.x, v.position.y});
        std::vector<PlanarEdge> edges;
        for (const StreetEdge &e : town.streets.graph().edges()) edges.emplace_back(e.a, e.b);
        StreetHierarchy hierarchy;
        std::vector<Stroke> strokes = strokesOf(points, edges, hierarchy.continuationDegrees);
        expectPartition(strokes, edges);
        auto length = [&](uint32_t e) {
            const PlanarPoint &a = points[edges[e].first], &b = points[edges[e].second];
            return std::hypot(b.x - a.x, b.y - a.y);
        };
        double total = 0, longest = 0;
        for (const Stroke &stroke : strokes) {
            double l = 0;
            for (uint32_t e : stroke) l += length(e);
            total += l, longest = std::max(longest, l);
        }
        std::vector<StreetClass> classes = classifyStreets(points, edges, hierarchy);
        double major = 0;
        for (uint32_t e = 0; e < edges.size(); ++e)
            if (classes[e] == StreetClass::Major) major += length(e);
        EXPECT_GE(major, hierarchy.majorShare * total);
        EXPECT_LT(major, hierarchy.majorShare * total + longest);
        EXPECT_LT(major, total);
    }
}

INSTANTIATE_TEST_SUITE_P(RuleSets, StreetHierarchyOfPatterns, testing::Values("grid", "organic", "radial"));

}  // namespace
}  // namespace veduta
