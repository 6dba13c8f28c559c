#include "slg/front_strip.h"

#include <algorithm>

namespace veduta {

namespace {

// A point of the line through edge e of the shape after it moved `depth` into the shape.
Vec2d movedPoint(const PlanShape &shape, size_t e, double depth) {
    return shape.start(e) + leftNormal(normalized(shape.end(e) - shape.start(e))) * depth;
}

std::optional<Vec2d> meet(Vec2d p, Vec2d u, Vec2d q, Vec2d v) {
    auto hit = intersectLines(p, u, q, v);
    if (!hit) return std::nullopt;
    return p + u * hit->s;
}

// The back of the strip: the front's points moved to `depth`, its ends on the sides' lines.
std::optional<std::vector<Vec2d>> backPoints(const PlanShape &face, const FaceSides &sides, double depth) {
    std::vector<Vec2d> back;
    size_t n = face.size();
    for (size_t i = 0; i <= sides.bottom.size(); ++i) {
        // Front point i lies between edges `before` and `after`; the end points lie on a side,
        // which does not move.
        size_t after = i < sides.bottom.size() ? sides.bottom[i] : (sides.bottom.back() + 1) % n;
        size_t before = (after + n - 1) % n;
        double dBefore = i == 0 ? 0 : depth, dAfter = i == sides.bottom.size() ? 0 : depth;
        Vec2d u = face.end(before) - face.start(before), v = face.end(after) - face.start(after);
        auto point = meet(movedPoint(face, before, dBefore), u, movedPoint(face, after, dAfter), v);
        if (!point && (i == 0 || i == sides.bottom.size())) return std::nullopt;  // a side along the front
        back.push_back(point ? *point : movedPoint(face, after, depth));
    }
    return back;
}

// Whether the strip lies inside the face: its back inside or on it, and no corner of the face
// inside the strip (where the face's back dips into the strip). The back's ends are crossings
// with the sides' lines, a rounding off them, and the corners of a side a rounding off the
// strip's end.
bool liesInside(const Polygon2d &strip, const PlanShape &face, const std::vector<Vec2d> &back) {
    if (!isSimple(strip) || signedArea(strip) <= 0) return false;
    double extent = 0;
    for (Vec2d p : face.points) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    double rounding = 1e-9 * (1 + extent);
    for (Vec2d p : back)
        if (distanceOutside(face.points, p) > rounding) return false;
    for (Vec2d p : face.points)
        if (sideOf(strip, p) == Side::Inside && distanceToBoundary(strip, p) > rounding) return false;
    return true;
}

}  // namespace

std::optional<FrontStrip> cutFrontStrip(const PlanShape &face, const FaceSides &sides, double depth,
                                        EdgeLocation back) {
    auto backs = backPoints(face, sides, depth);
    if (!backs) return std::nullopt;
    const std::vector<Vec2d> &c = *backs;
    size_t k = sides.bottom.size();

    FrontStrip result;
    PlanShape &strip = result.strip;
    for (size_t i = 0; i < k; ++i) {
        strip.points.push_back(face.points[sides.bottom[i]]);
        strip.locations.push_back(face.locations[sides.bottom[i]]);
    }
    strip.points.push_back(face.end(sides.bottom.back()));
    strip.locations.push_back(face.locations[sides.right.front()]);
    for (size_t i = k; i > 0; --i) {
        strip.points.push_back(c[i]);
        strip.locations.push_back(back);
    }
    strip.points.push_back(c[0]);
    strip.locations.push_back(face.locations[sides.left.back()]);
    if (!liesInside(strip.points, face, c)) return std::nullopt;

    for (size_t i = 0; i < k; ++i) result.stripSides.bottom.push_back(i);
    result.stripSides.right = {k};
    for (size_t i = k + 1; i < 2 * k + 1; ++i) result.stripSides.top.push_back(i);
    result.stripSides.left = {2 * k + 1};
    for (size_t i = 0; i < k; ++i)
        result.quads.push_back({face.points[sides.bottom[i]], face.end(sides.bottom[i]), c[i + 1], c[i]});

    if (auto behind = moveSides(face, sides, {depth, 0, 0, 0}, back)) {
        result.behind = std::move(behind->shape);
        result.behindSides = sidesAfterMove(sides, behind->source);
    }
    return result;
}

}  // namespace veduta
