#include "streets/street_constraints.h"

#include <gtest/gtest.h>

#include <cmath>

namespace veduta {
namespace {

const Vec3f kEast{1, 0, 0};

// A street graph with its start vertex at the origin, and plain edges to add.
struct Ground {
    StreetGraph graph;
    VertexId start = graph.addVertex({0, 0, 0});
    EdgeId street(const Vec3f &a, const Vec3f &b) { return graph.addEdge(graph.addVertex(a), graph.addVertex(b)); }
    SegmentPlan plan(const Vec3f &direction, float length) const {
        return planSegment(graph, {graph.vertex(start).position, start}, direction, length, StreetConstraints{});
    }
};

void expectAt(const Vec3f &actual, const Vec3f &expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
    EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

TEST(StreetConstraints, AStreetWithNothingNearGoesAsProposed) {
    Ground ground;
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::Normal);
    EXPECT_EQ(plan.target, SegmentTarget::NewVertex);
    expectAt(plan.end, {10, 0, 0});
    EXPECT_FLOAT_EQ(plan.length, 10);
    EXPECT_EQ(plan.turnDegrees, 0);
}

TEST(StreetConstraints, StreetsShorterThanTheMinimumOrBeyondTheLimitFail) {
    Ground ground;
    EXPECT_EQ(ground.plan(kEast, 2.9f).code, QueryResult::Failed);
    EXPECT_EQ(ground.plan(kEast, 3.0f).code, QueryResult::Normal);
    EXPECT_EQ(ground.plan(kEast, 2e4f).code, QueryResult::Failed);
    EXPECT_EQ(ground.plan({0, 0, 0}, 10).code, QueryResult::Failed);
    // Steep enough that its ground-plane length is below the minimum.
    EXPECT_EQ(ground.plan({1, 0, 4}, 10).code, QueryResult::Failed);
}

TEST(StreetConstraints, ANearVertexAheadBendsTheStreetOntoIt) {
    Ground ground;
    VertexId near = ground.graph.addVertex({10, 1, 0});
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::NearestNeighbour);
    EXPECT_EQ(plan.target, SegmentTarget::Vertex);
    EXPECT_EQ(plan.vertex, near);
    EXPECT_FLOAT_EQ(plan.length, std::sqrt(101.0f));
    // To the left, so a negative `&` turn.
    EXPECT_NEAR(plan.turnDegrees, -std::atan2(1.0, 10.0) * 180 / 3.14159265358979, 1e-4);
}

TEST(StreetConstraints, OfTheVerticesInTheHullTheNearestToTheEndIsTaken) {
    Ground ground;
    ground.graph.addVertex({8, -2, 0});
    VertexId nearest = ground.graph.addVertex({11, 1, 0});
    EXPECT_EQ(ground.plan(kEast, 10).vertex, nearest);
}

TEST(StreetConstraints, VerticesOutsideTheHullOrAtAnotherHeightAreIgnored) {
    Ground ground;
    ground.graph.addVertex({10, 2.6f, 0});  // the hull is 2.5 wide for a length of 10
    ground.graph.addVertex({13.6f, 0, 0});  // and ends 2.5 past the end
    ground.graph.addVertex({-1, 0, 0});     // and does not reach behind the start
    ground.graph.addVertex({10, 0, 5});     // on another level
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Normal);
}

TEST(StreetConstraints, ANearVertexThatWouldLeaveTooShortAStreetIsNotTaken) {
    Ground ground;
    ground.graph.addVertex({2, 0.5f, 0});
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Normal);
}

TEST(StreetConstraints, ANearVertexIsNotReachedThroughAStreet) {
    Ground ground;
    ground.graph.addVertex({10, 2, 0});
    EdgeId wall = ground.street({5, -5, 0}, {5, 5, 0});
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::Intersection);
    EXPECT_EQ(plan.edge, wall);
}

TEST(StreetConstraints, AStreetCrossedIsCutAtTheCrossing) {
    Ground ground;
    EdgeId crossed = ground.street({5, -5, 0}, {5, 5, 0});
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::Intersection);
    EXPECT_EQ(plan.target, SegmentTarget::EdgeSplit);
    EXPECT_EQ(plan.edge, crossed);
    expectAt(plan.end, {5, 0, 0});
    EXPECT_FLOAT_EQ(plan.length, 5);
}

TEST(StreetConstraints, TheNearestOfSeveralStreetsCrossedIsMet) {
    Ground ground;
    ground.street({8, -5, 0}, {8, 5, 0});
    EdgeId nearer = ground.street({6, -5, 0}, {6, 5, 0});
    EXPECT_EQ(ground.plan(kEast, 10).edge, nearer);
}

TEST(StreetConstraints, AStreetJustBeyondTheEndIsMetForward) {
    Ground ground;
    ground.street({12, -5, 0}, {12, 5, 0});
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::ForwardIntersection);
    expectAt(plan.end, {12, 0, 0});
    EXPECT_FLOAT_EQ(plan.length, 12);
    Ground farther;
    farther.street({12.6f, -5, 0}, {12.6f, 5, 0});  // beyond collisionOffset 2.5
    EXPECT_EQ(farther.plan(kEast, 10).code, QueryResult::Normal);
}

TEST(StreetConstraints, AMeetingNearAStreetsEndGoesToThatEnd) {
    Ground ground;
    ground.street({5, -2.8f, 0}, {5, 10, 0});  // a cut would leave 2.8 < 3
    SegmentPlan plan = ground.plan(kEast, 10);
    EXPECT_EQ(plan.code, QueryResult::Intersection);
    EXPECT_EQ(plan.target, SegmentTarget::Vertex);
    expectAt(plan.end, {5, -2.8f, 0});
    EXPECT_NEAR(plan.length, std::hypot(5.0f, 2.8f), 1e-5f);
}

TEST(StreetConstraints, AShallowCrossingFails) {
    Ground ground;
    ground.street({0.5f, -2, 0}, {20.5f, 6, 0});  // 21.8° to the proposal
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Failed);
}

TEST(StreetConstraints, ACrossingTooCloseToTheStartFails) {
    Ground ground;
    ground.street({2, -5, 0}, {2, 5, 0});
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Failed);
}

TEST(StreetConstraints, AStreetTooCloseInAngleToOneAtItsStartFails) {
    Ground ground;
    ground.graph.addEdge(ground.start, ground.graph.addVertex({10, 9, 0}));  // 42° away
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Failed);
    Ground wider;
    wider.graph.addEdge(wider.start, wider.graph.addVertex({10, 11, 0}));  // 47.7° away
    EXPECT_EQ(wider.plan(kEast, 10).code, QueryResult::Normal);
}

TEST(StreetConstraints, StreetsOnAnotherLevelAreNotMet) {
    Ground ground;
    ground.street({5, -5, 6}, {5, 5, 6});
    EXPECT_EQ(ground.plan(kEast, 10).code, QueryResult::Normal);
}

TEST(StreetConstraints, AStreetFromAFreePointMeetsStreetsLikeAnyOther) {
    StreetGraph graph;
    EdgeId crossed = graph.addEdge(graph.addVertex({5, -5, 0}), graph.addVertex({5, 5, 0}));
    SegmentPlan plan = planSegment(graph, {{0, 1, 0}}, kEast, 10, StreetConstraints{});
    EXPECT_EQ(plan.code, QueryResult::Intersection);
    EXPECT_EQ(plan.edge, crossed);
    expectAt(plan.end, {5, 1, 0});
}

TEST(StreetConstraints, ALiftGoesAsProposed) {
    Ground ground;
    ground.street({-5, 0, 5}, {5, 0, 5});
    SegmentPlan plan = ground.plan({0, 0, 1}, 10);
    EXPECT_EQ(plan.code, QueryResult::Normal);
    expectAt(plan.end, {0, 0, 10});
}

}  // namespace
}  // namespace veduta
