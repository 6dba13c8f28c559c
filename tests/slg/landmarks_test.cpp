// How many landmarks, and where (digest-003 §2.2 step 2, §2.3, §8.2).
#include <gtest/gtest.h>

#include <cmath>

#include "slg/landmarks.h"

namespace veduta {
namespace {

PlanParameters growth(double scale, double exponent, int minimum) {
    PlanParameters p;
    p.rule = LandmarkRule::Growth;
    p.scale = scale;
    p.exponent = exponent;
    p.minimumCount = minimum;
    return p;
}

TEST(LandmarkCount, RoomsOfTheThesisApartments) {
    // L1551 and footnote 82: scale 1, exponent 3, at least 3: 50, 80, 200 m² give 3, 4, 5 rooms,
    // and ∛343 is 7, not the 6 a plain floor of pow() gives.
    PlanParameters apartment = growth(1, 3, 3);
    EXPECT_EQ(landmarkCount(apartment, 50, 0, 4), 3);
    EXPECT_EQ(landmarkCount(apartment, 80, 0, 4), 4);
    EXPECT_EQ(landmarkCount(apartment, 200, 0, 4), 5);
    EXPECT_EQ(landmarkCount(apartment, 343, 0, 4), 7);
    EXPECT_EQ(landmarkCount(apartment, 10, 0, 4), 3);  // the minimum
    // Table 13's storey (15; 2): 100 m² gives two apartments.
    EXPECT_EQ(landmarkCount(growth(15, 2, 1), 100, 0, 4), 2);
}

TEST(LandmarkCount, PerimeterRuleOfABlock) {
    // A 100 × 100 m block of 150 m² lots: ⌊400/√150 − 4⌋ = 28.
    PlanParameters block;
    block.rule = LandmarkRule::Perimeter;
    block.averageArea = 150;
    EXPECT_EQ(landmarkCount(block, 10000, 400, 4), 28);
    block.count = 5;
    EXPECT_EQ(landmarkCount(block, 10000, 400, 4), 5);
}

TEST(LengthLimits, TheLimitsOfTheThesisLevels) {
    auto limits = [](double area, double ratio) {
        PlanParameters p;
        p.averageArea = area;
        p.sideRatio = ratio;
        return lengthLimits(p);
    };
    EXPECT_NEAR(limits(25000, 0.5).minimum, 111.8, 0.05);  // City
    EXPECT_NEAR(limits(25000, 0.5).maximum, 316.2, 0.05);
    EXPECT_NEAR(limits(5000, 0.5).minimum, 50, 1e-9);  // District
    EXPECT_NEAR(limits(5000, 0.5).maximum, 141.4, 0.05);
    EXPECT_NEAR(limits(30, 0.5).minimum, 3.87, 0.005);  // Storey
    EXPECT_NEAR(limits(30, 0.5).maximum, 10.95, 0.005);
    EXPECT_NEAR(limits(10, 1.0 / 3).minimum, 1.83, 0.005);  // Apartment: no room side under 1.83 m
    EXPECT_NEAR(limits(10, 1.0 / 3).maximum, 9.49, 0.005);
}

TEST(LandmarksPerEdge, TheLongestEdgeOverItsCountTakesTheNext) {
    EXPECT_EQ(landmarksPerEdge({30}, 2), (std::vector<int>{2}));
    EXPECT_EQ(landmarksPerEdge({30, 10, 30, 10}, 4), (std::vector<int>{2, 0, 2, 0}));
    // 15, 10, 15, 10 → 10, 10, 15, 10 → 10, 10, 10, 10; then the first of the tie, and 10 > 7.5.
    EXPECT_EQ(landmarksPerEdge({30, 10, 30, 10}, 6), (std::vector<int>{3, 1, 2, 0}));
}

TEST(LandmarkPositions, TwoOnOneEdgeGiveThirds) {
    PlanRandom random(1, 2, RandomStream::SlgPlan);
    std::vector<double> t = landmarkPositions(2, 30, 0, false, false, 0, random, 0);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_DOUBLE_EQ(t[0] * 30, 10);
    EXPECT_DOUBLE_EQ(t[1] * 30, 20);
}

TEST(LandmarkPositions, JitterStaysWithinItsShareOfTheSpacing) {
    for (uint32_t id = 0; id < 50; ++id) {
        PlanRandom random(7, id, RandomStream::SlgPlan);
        std::vector<double> t = landmarkPositions(3, 40, 0.1, false, false, 0, random, 0);
        for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(t[i] - (i + 1) * 0.25), 0.1 * 0.25 + 1e-12);
    }
}

TEST(LandmarkPositions, ConcaveCornersPullTheNearestToLengthMin) {
    PlanRandom random(1, 2, RandomStream::SlgPlan);
    std::vector<double> t = landmarkPositions(3, 40, 0, true, true, 4, random, 0);
    EXPECT_DOUBLE_EQ(t[0] * 40, 4);
    EXPECT_DOUBLE_EQ(t[1] * 40, 20);
    EXPECT_DOUBLE_EQ(t[2] * 40, 36);
    // One landmark between two concave corners goes to the first.
    EXPECT_DOUBLE_EQ(landmarkPositions(1, 40, 0, true, true, 4, random, 0)[0] * 40, 4);
}

TEST(PlaceLandmarks, SplitsTheOutlineAndAimsTheRaysInwards) {
    PlanParameters p = growth(1, 3, 3);
    p.count = 4;
    SlgGraph graph =
        outlineGraph({{0, 0}, {12, 0}, {12, 6}, {0, 6}}, std::vector<EdgeLocation>(4, EdgeLocation::Street));
    std::vector<SlgNodeId> landmarks = placeLandmarks(graph, p, PlanRandom(1, 1, RandomStream::SlgPlan));
    // Lengths 12, 6, 12, 6: the bottom takes the first and (on the tie at 6) the third.
    ASSERT_EQ(landmarks.size(), 4u);
    EXPECT_EQ(graph.position(landmarks[0]), (Vec2d{4, 0}));
    EXPECT_EQ(graph.position(landmarks[1]), (Vec2d{8, 0}));
    EXPECT_EQ(graph.position(landmarks[2]), (Vec2d{12, 3}));
    EXPECT_EQ(graph.position(landmarks[3]), (Vec2d{6, 6}));
    EXPECT_EQ(graph.node(landmarks[0]).ray, (Vec2d{0, 1}));
    EXPECT_EQ(graph.node(landmarks[2]).ray, (Vec2d{-1, 0}));
    EXPECT_EQ(graph.node(landmarks[3]).ray, (Vec2d{0, -1}));
    EXPECT_EQ(graph.edges().size(), 8u);
    p.count = 1;
    SlgGraph alone =
        outlineGraph({{0, 0}, {12, 0}, {12, 6}, {0, 6}}, std::vector<EdgeLocation>(4, EdgeLocation::Street));
    EXPECT_TRUE(placeLandmarks(alone, p, PlanRandom(1, 1, RandomStream::SlgPlan)).empty());
    EXPECT_EQ(alone.edges().size(), 4u);
}

}  // namespace
}  // namespace veduta
