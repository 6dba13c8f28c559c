#include "slg/stairs.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace veduta {

namespace {

constexpr double kRiser = 0.18;   // aimed at: equal risers round it come out 0.17–0.19 m in a storey
constexpr double kPace = 0.63;    // Blondel's rule: two risers and a going
constexpr double kWidth = 1.0;    // a house's flight (DIN 18065: 0.8 m at least)
constexpr double kOnWall = 1e-9;  // a corner worked out in double stands this close to the wall it is on

// How far along `out` from a corner of a room, where the walls run in along `in` and on along
// `out`, a flight against `out` must start for its far edge, `width` into the room, to clear
// the wall along `in`: nothing at a right angle, width · cot of an acute one. A reflex corner
// turns that wall away from the flight.
double clearance(Vec2d in, Vec2d out, double width) {
    double turn = cross(in, out);
    return turn > 0 ? std::max(0.0, -width * dot(in, out) / turn) : 0;
}

// The flight's outline lies in the room: its corners do and no corner of the room lies inside it.
bool fitsIn(const Polygon2d &room, const Flight &flight) {
    double run = flight.risers * flight.going;
    Polygon2d outline = {flight.at(0, 0), flight.at(run, 0), flight.at(run, flight.width), flight.at(0, flight.width)};
    auto inside = [&](Vec2d p) {
        return sideOf(outline, p) == Side::Inside && distanceToBoundary(outline, p) > kOnWall;
    };
    return std::ranges::all_of(outline, [&](Vec2d p) { return distanceOutside(room, p) <= kOnWall; }) &&
        std::ranges::none_of(room, inside);
}

}  // namespace

std::optional<Flight> straightFlight(const Polygon2d &room, double height) {
    Polygon2d sides;
    for (size_t c : turningPoints(room)) sides.push_back(room[c]);
    size_t n = sides.size(), longest = longestEdge(sides);
    auto corner = [&](size_t i) { return sides[i % n]; };
    Vec2d a = corner(longest), b = corner(longest + 1);
    Vec2d up = normalized(b - a);
    double from = clearance(a - corner(longest + n - 1), up, kWidth);
    double to = length(b - a) - clearance(up, corner(longest + 2) - b, kWidth);

    Flight flight;
    flight.risers = std::max(1, int(std::lround(height / kRiser)));
    flight.riser = height / flight.risers;
    // A going's floor before the first riser: flush with the wall it would face that wall in its
    // plane, and there would be nowhere to step onto the flight from.
    flight.going = std::min(kPace - 2 * flight.riser, (to - from) / (flight.risers + 1));
    if (flight.going <= 0) return std::nullopt;
    flight.foot = a + up * (from + flight.going);
    flight.up = up;
    flight.across = leftNormal(up);
    flight.width = kWidth;
    if (!fitsIn(room, flight)) return std::nullopt;
    return flight;
}

Polygon2d tread(const Flight &flight, int step) {
    double front = step * flight.going, back = front + flight.going;
    return {flight.at(front, 0), flight.at(back, 0), flight.at(back, flight.width), flight.at(front, flight.width)};
}

}  // namespace veduta
