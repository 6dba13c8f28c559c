// The flight of stairs in a stairwell (digest-003 §3.2, §3.5): equal risers of 0.17–0.19 m up
// exactly one storey, laid along the room's longest side, every step inside the room.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "slg/stairs.h"

namespace veduta {
namespace {

// A room with its longest side from a to b (counter-clockwise, the room on its left).
struct Room {
    Polygon2d points;
    Vec2d a, b;
};

double distanceToLine(Vec2d p, Vec2d a, Vec2d b) { return std::abs(cross(b - a, p - a)) / length(b - a); }

void expectInside(const Flight &flight, const Room &room) {
    for (int i = 0; i < flight.risers; ++i)
        for (Vec2d p : tread(flight, i)) EXPECT_LE(distanceOutside(room.points, p), 1e-9) << i;
    // Along the longest side: the front corners at the wall stand on it, the way up runs with it.
    EXPECT_LT(distanceToLine(flight.foot, room.a, room.b), 1e-9);
    EXPECT_LT(distanceToLine(tread(flight, flight.risers - 1)[1], room.a, room.b), 1e-9);
    EXPECT_NEAR(dot(flight.up, normalized(room.b - room.a)), 1, 1e-12);
}

TEST(Stairs, EqualRisersClimbTheStoreyExactly) {
    Room room{{{0, 0}, {2.6, 0}, {2.6, 2.4}, {0, 2.4}}, {0, 0}, {2.6, 0}};
    for (double height = 2.5; height <= 4.5; height += 0.1) {
        auto flight = straightFlight(room.points, height);
        ASSERT_TRUE(flight) << height;
        EXPECT_NEAR(flight->risers * flight->riser, height, 1e-6);
        EXPECT_GE(flight->riser, 0.17) << height;
        EXPECT_LE(flight->riser, 0.19) << height;
        // Blondel's pace at most; the side is shorter than a comfortable flight here.
        EXPECT_GT(flight->going, 0);
        EXPECT_LE(2 * flight->riser + flight->going, 0.63 + 1e-12);
        // The whole side, as steep as it takes, with a going's floor before the first riser.
        EXPECT_NEAR((flight->risers + 1) * flight->going, 2.6, 1e-9);
        EXPECT_NEAR(length(flight->foot - room.a), flight->going, 1e-9);
        expectInside(*flight, room);
    }
}

Polygon2d rotated(const Polygon2d &polygon, double degrees) {
    double c = std::cos(degrees * std::numbers::pi / 180), s = std::sin(degrees * std::numbers::pi / 180);
    Polygon2d out;
    for (Vec2d p : polygon) out.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    return out;
}

TEST(Stairs, EveryStepLiesInsideTheRoomAlongItsLongestSide) {
    Polygon2d turned = rotated({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, 30);
    std::vector<Room> rooms = {
        {{{0, 0}, {6, 0}, {6, 3}, {0, 3}}, {0, 0}, {6, 0}},  // long enough for Blondel's pace
        {{{5, 1}, {5, 3.5}, {2, 3.5}, {2, 1}}, {5, 3.5}, {2, 3.5}},
        {turned, turned[0], turned[1]},
        // An acute corner (61°) where the longest side starts, an obtuse one where it ends: the
        // flight starts far enough along for its far edge to clear the slanting wall.
        {{{0, 0}, {3, 0}, {3.4, 2.2}, {1.2, 2.2}}, {0, 0}, {3, 0}},
        {{{0, 0}, {4, 0}, {4, 1.2}, {1.5, 1.2}, {1.5, 2.5}, {0, 2.5}}, {0, 0}, {4, 0}},  // an L
    };
    for (size_t r = 0; r < rooms.size(); ++r) {
        SCOPED_TRACE(r);
        auto flight = straightFlight(rooms[r].points, 3);
        ASSERT_TRUE(flight);
        EXPECT_EQ(flight->risers, 17);
        expectInside(*flight, rooms[r]);
    }
    EXPECT_GT(length(straightFlight(rooms[3].points, 3)->foot), 0.5) << "cleared the acute corner";
}

TEST(Stairs, ARoomWithNoPlaceForAFlightHasNone) {
    EXPECT_FALSE(straightFlight({{0, 0}, {4, 0}, {4, 0.8}, {0, 0.8}}, 3)) << "narrower than a flight";
    // A U: the longest side is its bottom, and the gap between the arms comes down into the flight.
    EXPECT_FALSE(straightFlight({{0, 0}, {5, 0}, {5, 3}, {3, 3}, {3, 0.6}, {2, 0.6}, {2, 3}, {0, 3}}, 3));
}

}  // namespace
}  // namespace veduta
