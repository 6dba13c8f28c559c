// The four sides of a face and moving them (digest-003 §2.4): the side decomposition of
// L1650–1666, moved sides whose ends slide along their neighbours (eq 24) and corners that
// move along their bisectors by d/sin(θ/2) (the digest's correction of eq 25).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "slg/face_sides.h"
#include "slg/subdivision.h"

namespace veduta {
namespace {

PlanShape shapeOf(Polygon2d points, EdgeLocation location = EdgeLocation::NeighbourArea) {
    std::vector<EdgeLocation> locations(points.size(), location);
    return {std::move(points), std::move(locations)};
}

void expectNear(Vec2d a, Vec2d b) {
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
}

TEST(FourSides, ARectangleHasOneEdgeOnEachSide) {
    FaceSides s = fourSides({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, 1);
    EXPECT_EQ(s.bottom, std::vector<size_t>{0});
    EXPECT_EQ(s.right, std::vector<size_t>{1});
    EXPECT_EQ(s.top, std::vector<size_t>{2});
    EXPECT_EQ(s.left, std::vector<size_t>{3});
}

TEST(FourSides, StraightRunsBelongToTheSideAndBendsToTheTop) {
    // Front of two edges with a street corner, a right side split at a crossing, a top that
    // bends, and a left side of one edge.
    Polygon2d face = {{0, 0}, {6, 0}, {10, 0}, {10, 3}, {10, 7}, {7, 9}, {3, 8}, {0, 8}};
    FaceSides s = fourSides(face, 2);
    EXPECT_EQ(s.bottom, (std::vector<size_t>{0, 1}));
    EXPECT_EQ(s.right, (std::vector<size_t>{2, 3}));
    EXPECT_EQ(s.top, (std::vector<size_t>{4, 5, 6}));
    EXPECT_EQ(s.left, std::vector<size_t>{7});
}

TEST(FourSides, ATriangleBeyondTheFrontHasNoTop) {
    FaceSides s = fourSides({{0, 0}, {8, 0}, {4, 5}}, 1);
    EXPECT_EQ(s.right, std::vector<size_t>{1});
    EXPECT_TRUE(s.top.empty());
    EXPECT_EQ(s.left, std::vector<size_t>{2});
}

TEST(FourSides, TheSidesOfEveryLotOfABlockCoverItsEdges) {
    Polygon2d outline = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    PlanParameters p;
    p.averageArea = 150;
    p.jitter = 0.05;
    Subdivision s = subdivide(outline, std::vector<EdgeLocation>(4, EdgeLocation::Street), p,
                              PlanRandom(3, 1, RandomStream::SlgPlan));
    for (const PlanFace *face : s.borderFaces()) {
        size_t front = std::ranges::find(face->path.nodes, face->right) - face->path.nodes.begin();
        FaceSides sides = fourSides(s.graph.polygon(face->path), front);
        EXPECT_EQ(sides.bottom.size() + sides.right.size() + sides.top.size() + sides.left.size(),
                  face->path.edges.size());
        for (size_t e : sides.bottom) EXPECT_TRUE(s.graph.edge(face->path.edges[e]).outer);
        for (size_t e : sides.right) EXPECT_FALSE(s.graph.edge(face->path.edges[e]).outer);
    }
}

TEST(MoveEdges, ASideMovedInSlidesItsEndsAlongTheSidesBeside) {
    // A trapezoid: its top moved down by 1 slides along the slanted right side.
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {8, 4}, {0, 4}});
    auto moved = moveEdges(shape, {0, 0, 1, 0}, EdgeLocation::HouseCorridor);
    ASSERT_TRUE(moved);
    ASSERT_EQ(moved->shape.size(), 4u);
    expectNear(moved->shape.points[2], {8.5, 3});
    expectNear(moved->shape.points[3], {0, 3});
    EXPECT_EQ(moved->shape.locations[2], EdgeLocation::HouseCorridor);
    EXPECT_EQ(moved->shape.locations[1], EdgeLocation::NeighbourArea);
}

TEST(MoveEdges, ACornerWithinASideMovesAlongItsBisectorByDOverSinHalfTheAngle) {
    // The top of a face bends by 60° at (5, 4): moved by d, that corner moves d/sin(60°)
    // along the bisector (eq 25 corrected), not d.
    double rise = 5 * std::tan(std::numbers::pi / 6);
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {10, 4}, {5, 4 + rise}, {0, 4}});
    double d = 0.75;
    auto moved = moveEdges(shape, {0, 0, d, d, 0}, EdgeLocation::Gap);
    ASSERT_TRUE(moved);
    Vec2d apex = moved->shape.points[3];
    EXPECT_NEAR(apex.x, 5, 1e-12);
    EXPECT_NEAR(4 + rise - apex.y, d / std::sin(std::numbers::pi / 3), 1e-12);
}

TEST(MoveEdges, ANegativeDistanceMovesOut) {
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {10, 6}, {0, 6}});
    auto moved = moveEdges(shape, {-0.5, -0.5, -0.5, -0.5}, EdgeLocation::Gap);
    ASSERT_TRUE(moved);
    EXPECT_NEAR(signedArea(moved->shape.points), 11 * 7, 1e-9);
}

TEST(MoveEdges, EdgesInOneLineMovedApartGetAJoin) {
    // The top is two edges in one line; only the right one moves, so a join runs across.
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {10, 6}, {5, 6}, {0, 6}});
    auto moved = moveEdges(shape, {0, 0, 1.5, 0, 0}, EdgeLocation::HouseCorridor);
    ASSERT_TRUE(moved);
    ASSERT_EQ(moved->shape.size(), 6u);
    expectNear(moved->shape.points[3], {5, 4.5});
    expectNear(moved->shape.points[4], {5, 6});
    EXPECT_EQ(moved->shape.locations[3], EdgeLocation::HouseCorridor) << "the join faces the corridor";
    EXPECT_EQ(moved->shape.locations[4], EdgeLocation::NeighbourArea);
    EXPECT_EQ(moved->source, (std::vector<size_t>{0, 1, 2, 3, 3, 4}));
    EXPECT_NEAR(signedArea(moved->shape.points), 60 - 7.5, 1e-9);
}

TEST(MoveEdges, ACornerSlidesPastAPointThatOnlySplitsTheLineBeside) {
    // The top is split 0.5 m from the right corner where a crossing of the plan's network sat;
    // the right side moving in by 1.5 m slides past it, and the point goes.
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {10, 6}, {9.5, 6}, {0, 6}});
    shape.locations[2] = EdgeLocation::Gap;
    auto moved = moveEdges(shape, {0, 1.5, 0, 0, 0}, EdgeLocation::HouseCorridor);
    ASSERT_TRUE(moved);
    EXPECT_EQ(moved->shape.points, (Polygon2d{{0, 0}, {8.5, 0}, {8.5, 6}, {0, 6}}));
    EXPECT_EQ(moved->source, (std::vector<size_t>{0, 1, 3, 4}));
    EXPECT_EQ(moved->shape.locations[1], EdgeLocation::HouseCorridor);
    EXPECT_EQ(moved->shape.locations[2], EdgeLocation::NeighbourArea) << "the line's other edge carries on";
}

TEST(MoveEdges, AFaceTooSmallForTheGapIsRefused) {
    PlanShape shape = shapeOf({{0, 0}, {10, 0}, {10, 3}, {0, 3}});
    EXPECT_FALSE(moveEdges(shape, {0, 0, 3, 0}, EdgeLocation::Gap)) << "no depth left";
    EXPECT_FALSE(moveEdges(shape, {0, 0, 4, 0}, EdgeLocation::Gap)) << "turned inside out";
    EXPECT_TRUE(moveEdges(shape, {0, 0, 2.9, 0}, EdgeLocation::Gap));
}

TEST(MoveSides, AStreetBetweenDistrictsHalvesItsWidthOnEachFace) {
    // City and District faces keep their bottom and move the rest by width/2 (L1339).
    PlanShape shape = shapeOf({{0, 0}, {100, 0}, {100, 80}, {0, 80}}, EdgeLocation::Street);
    FaceSides sides = fourSides(shape.points, 1);
    auto moved = moveSides(shape, sides, {0, 5, 5, 5}, EdgeLocation::Street);
    ASSERT_TRUE(moved);
    EXPECT_EQ(moved->shape.points, (Polygon2d{{5, 0}, {95, 0}, {95, 75}, {5, 75}}));
    EXPECT_DOUBLE_EQ(sideLength(moved->shape, sides.bottom), 90);
}

}  // namespace
}  // namespace veduta
