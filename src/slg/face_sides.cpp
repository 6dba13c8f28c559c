#include "slg/face_sides.h"

#include <algorithm>

#include "core/check.h"

namespace veduta {

namespace {

bool runsStraightOn(const Polygon2d &face, size_t edge, size_t next) {
    size_t n = face.size();
    Vec2d a = face[edge], b = face[(edge + 1) % n], c = face[(next + 1) % n];
    return turnAt(a, b, c) == Turn::Straight && dot(b - a, c - b) > 0;
}

// A point on edge i's line after it moved: its start, moved.
Vec2d movedStart(const PlanShape &shape, size_t i, double distance) {
    return shape.start(i) + leftNormal(normalized(shape.end(i) - shape.start(i))) * distance;
}

}  // namespace

FaceSides fourSides(const Polygon2d &face, size_t frontEdges) {
    size_t n = face.size();
    VEDUTA_CHECK(frontEdges >= 1 && frontEdges + 2 <= n, "a face has a front and at least two sides beside it");
    FaceSides sides;
    for (size_t i = 0; i < frontEdges; ++i) sides.bottom.push_back(i);
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
    auto add = [&](Vec2d point, size_t source) {
        moved.shape.points.push_back(point);
        moved.shape.locations.push_back(distances[source] != 0 ? gap : shape.locations[source]);
        moved.source.push_back(source);
    };
    for (size_t i = 0; i < n; ++i) {
        size_t before = (i + n - 1) % n;
        Vec2d u = shape.end(before) - shape.start(before), v = shape.end(i) - shape.start(i);
        Vec2d p = movedStart(shape, before, distances[before]), q = movedStart(shape, i, distances[i]);
        if (auto hit = intersectLines(p, u, q, v);
            hit && turnAt(shape.start(before), shape.start(i), shape.end(i)) != Turn::Straight) {
            add(p + u * hit->s, i);
            continue;
        }
        if (dot(u, v) <= 0) return std::nullopt;  // a spike: the shape folds back on itself here
        Vec2d shifted = shape.start(i) + leftNormal(normalized(u)) * distances[before];
        if (distances[before] != distances[i]) {
            // The join across from the line `before` moved to, to the one edge i moved to.
            add(shifted, i);
            moved.shape.locations.back() = gap;
        }
        add(q, i);
    }
    // Where a join was added its point came first: edge i's own start follows it.
    const Polygon2d &points = moved.shape.points;
    if (!isSimple(points) || signedArea(points) <= 0) return std::nullopt;
    for (size_t k = 0; k < points.size(); ++k) {
        size_t s = moved.source[k];
        Vec2d now = points[(k + 1) % points.size()] - points[k];
        bool join = k + 1 < points.size() && moved.source[k + 1] == s;
        if (!join && dot(now, shape.end(s) - shape.start(s)) <= 0) return std::nullopt;
    }
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

double sideLength(const PlanShape &shape, const std::vector<size_t> &edges) {
    double total = 0;
    for (size_t e : edges) total += shape.edgeLength(e);
    return total;
}

}  // namespace veduta
