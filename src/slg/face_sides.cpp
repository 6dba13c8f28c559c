#include "slg/face_sides.h"

#include <algorithm>

#include "core/check.h"

namespace veduta {

namespace {

bool runsStraightOn(const Polygon2d &face, size_t edge, size_t next) {
    size_t n = face.size();
    Vec2d a = face[edge], b = face[(edge + 1) % n], c = face[(next + 1) % n];
    return goesStraightOn(a, b, c);
}

// A point on edge i's line after it moved: its start, moved.
Vec2d movedStart(const PlanShape &shape, size_t i, double distance) {
    return shape.start(i) + leftNormal(normalized(shape.end(i) - shape.start(i))) * distance;
}

// Whether output edge k of a moved shape is a join: a join's point comes just before the start
// of the edge it leads to, which has the same source.
bool isJoin(const MovedShape &moved, size_t k) {
    return k + 1 < moved.source.size() && moved.source[k + 1] == moved.source[k];
}

// An edge that turned round when its neighbour moved past its end: a corner of a moved side
// slid beyond a point that only split a straight line (a crossing of the plan's network on a
// face's top). The point is dropped and the line's other edge carries on from the corner. An
// edge turned round between two true corners means the face is too small: false.
bool dropOvertakenPoints(MovedShape &moved, std::vector<bool> &straight, const PlanShape &original) {
    auto erase = [&](size_t k) {
        moved.shape.points.erase(moved.shape.points.begin() + long(k));
        moved.shape.locations.erase(moved.shape.locations.begin() + long(k));
        moved.source.erase(moved.source.begin() + long(k));
        straight.erase(straight.begin() + long(k));
    };
    for (bool again = true; again;) {
        again = false;
        size_t m = moved.shape.points.size();
        if (m < 3) return false;
        for (size_t k = 0; k < m && !again; ++k) {
            size_t s = moved.source[k], next = (k + 1) % m;
            Vec2d now = moved.shape.points[next] - moved.shape.points[k];
            if (isJoin(moved, k) || dot(now, original.end(s) - original.start(s)) > 0) continue;
            if (straight[next]) {
                // Edge k vanishes; the edge after it starts at point k instead.
                moved.shape.locations[k] = moved.shape.locations[next];
                moved.source[k] = moved.source[next];
                erase(next);
            } else if (straight[k]) {
                erase(k);  // the edge before, in one line with edge k, runs on to its end
            } else {
                return false;
            }
            again = true;
        }
    }
    return true;
}

}  // namespace

FaceSides fourSides(const Polygon2d &face, size_t frontEdges) {
    size_t n = face.size();
    VEDUTA_CHECK(frontEdges >= 1 && frontEdges + 1 <= n, "a face has a front and a side");
    FaceSides sides;
    for (size_t i = 0; i < frontEdges; ++i) sides.bottom.push_back(i);
    if (frontEdges + 1 == n) {
        sides.right = sides.left = {n - 1};
        return sides;
    }
    size_t first = frontEdges, last = n - 1;
    sides.right.push_back(first);
    while (first + 1 < last && runsStraightOn(face, first, first + 1)) sides.right.push_back(++first);
    sides.left.push_back(last);
    while (last - 1 > first && runsStraightOn(face, last - 1, last)) sides.left.push_back(--last);
    std::ranges::reverse(sides.left);
    for (size_t i = first + 1; i < last; ++i) sides.top.push_back(i);
    return sides;
}

std::optional<MovedShape> moveEdges(const PlanShape &shape, const std::vector<double> &distances, EdgeLocation gap) {
    size_t n = shape.size();
    VEDUTA_CHECK(distances.size() == n && shape.locations.size() == n, "a distance and a location per edge");
    MovedShape moved;
    std::vector<bool> straight;  // the point lies within one moved line
    auto add = [&](Vec2d point, size_t source, bool within) {
        moved.shape.points.push_back(point);
        moved.shape.locations.push_back(distances[source] != 0 ? gap : shape.locations[source]);
        moved.source.push_back(source);
        straight.push_back(within);
    };
    for (size_t i = 0; i < n; ++i) {
        size_t before = (i + n - 1) % n;
        Vec2d u = shape.end(before) - shape.start(before), v = shape.end(i) - shape.start(i);
        Vec2d p = movedStart(shape, before, distances[before]), q = movedStart(shape, i, distances[i]);
        if (auto hit = intersectLines(p, u, q, v);
            hit && !goesStraightOn(shape.start(before), shape.start(i), shape.end(i))) {
            add(p + u * hit->s, i, false);
            continue;
        }
        if (dot(u, v) <= 0) return std::nullopt;  // a spike: the shape folds back on itself here
        if (distances[before] != distances[i]) {
            // The join across from the line `before` moved to, to the one edge i moved to.
            add(shape.start(i) + leftNormal(normalized(u)) * distances[before], i, false);
            moved.shape.locations.back() = gap;
            add(q, i, false);
        } else {
            add(q, i, true);
        }
    }
    if (!dropOvertakenPoints(moved, straight, shape)) return std::nullopt;
    const Polygon2d &points = moved.shape.points;
    if (!isSimple(points) || signedArea(points) <= 0) return std::nullopt;
    return moved;
}

std::optional<MovedShape> moveSides(const PlanShape &shape, const FaceSides &sides, SideDistances distances,
                                    EdgeLocation gap) {
    std::vector<double> perEdge(shape.size(), 0);
    for (auto [edges, distance] : {std::pair{&sides.bottom, distances.bottom}, std::pair{&sides.right, distances.right},
                                   std::pair{&sides.top, distances.top}, std::pair{&sides.left, distances.left}})
        for (size_t e : *edges) perEdge[e] = distance;
    return moveEdges(shape, perEdge, gap);
}

FaceSides sidesAfterMove(const FaceSides &before, const std::vector<size_t> &source) {
    FaceSides after;
    for (size_t k = 0; k < source.size(); ++k)
        for (auto [from, to] : {std::pair{&before.bottom, &after.bottom}, std::pair{&before.right, &after.right},
                                std::pair{&before.top, &after.top}, std::pair{&before.left, &after.left}})
            if (std::ranges::find(*from, source[k]) != from->end()) to->push_back(k);
    return after;
}

double sideLength(const PlanShape &shape, const std::vector<size_t> &edges) {
    double total = 0;
    for (size_t e : edges) total += shape.edgeLength(e);
    return total;
}

}  // namespace veduta
