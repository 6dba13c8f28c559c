#include "slg/plan_geometry.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <limits>
#include <numbers>

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

Point point(Vec2d p) { return {p.x, p.y}; }

std::vector<Point> points(const Polygon2d &polygon) {
    std::vector<Point> result;
    result.reserve(polygon.size());
    for (Vec2d p : polygon) result.push_back(point(p));
    return result;
}

constexpr double kDegrees = 180 / std::numbers::pi;

}  // namespace

Vec2d vertexMean(const Polygon2d &polygon) {
    Vec2d sum;
    for (Vec2d p : polygon) sum = sum + p;
    return sum * (1.0 / double(polygon.size()));
}

double angle180(Vec2d a, Vec2d b) {
    double cosine = dot(a, b) / (length(a) * length(b));
    return std::acos(std::clamp(cosine, -1.0, 1.0)) * kDegrees;
}

double angle360(Vec2d a, Vec2d b) {
    double turned = (std::atan2(b.y, b.x) - std::atan2(a.y, a.x)) * kDegrees;
    if (turned < 0) turned += 360;
    return turned >= 360 ? turned - 360 : turned;
}

Turn turnAt(Vec2d p, Vec2d q, Vec2d r) {
    switch (CGAL::orientation(point(p), point(q), point(r))) {
    case CGAL::LEFT_TURN: return Turn::Left;
    case CGAL::RIGHT_TURN: return Turn::Right;
    default: return Turn::Straight;
    }
}

bool goesStraightOn(Vec2d p, Vec2d q, Vec2d r) {
    constexpr double kRounding = 1e-9;
    Vec2d u = q - p, v = r - q;
    return dot(u, v) > 0 && std::abs(cross(u, v)) <= kRounding * length(u) * length(v);
}

size_t longestEdge(const Polygon2d &polygon) {
    auto edge = [&](size_t i) { return length(polygon[(i + 1) % polygon.size()] - polygon[i]); };
    size_t longest = 0;
    for (size_t i = 1; i < polygon.size(); ++i)
        if (edge(i) > edge(longest)) longest = i;
    return longest;
}

std::vector<size_t> turningPoints(const Polygon2d &polygon) {
    std::vector<size_t> corners;
    size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i)
        if (!goesStraightOn(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n])) corners.push_back(i);
    return corners;
}

bool isReflexCorner(const Polygon2d &ccw, size_t i) {
    size_t n = ccw.size();
    return turnAt(ccw[(i + n - 1) % n], ccw[i], ccw[(i + 1) % n]) == Turn::Right;
}

std::optional<LineHit> intersectLines(Vec2d p, Vec2d u, Vec2d q, Vec2d v) {
    double d = cross(u, v);
    if (d == 0) return std::nullopt;
    Vec2d w = q - p;
    return LineHit{cross(w, v) / d, cross(w, u) / d};
}

Side sideOf(const Polygon2d &polygon, Vec2d p) {
    std::vector<Point> outline = points(polygon);
    switch (CGAL::bounded_side_2(outline.begin(), outline.end(), point(p), Kernel())) {
    case CGAL::ON_BOUNDED_SIDE: return Side::Inside;
    case CGAL::ON_BOUNDARY: return Side::Boundary;
    default: return Side::Outside;
    }
}

double distanceOutside(const Polygon2d &polygon, Vec2d point) {
    return sideOf(polygon, point) == Side::Outside ? distanceToBoundary(polygon, point) : 0;
}

double distanceToBoundary(const Polygon2d &polygon, Vec2d point) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2d a = polygon[i], v = polygon[(i + 1) % polygon.size()] - a;
        double t = std::clamp(dot(point - a, v) / dot(v, v), 0.0, 1.0);
        nearest = std::min(nearest, length(a + v * t - point));
    }
    return nearest;
}

bool isSimple(const Polygon2d &polygon) {
    if (polygon.size() < 3) return false;
    for (size_t i = 0; i < polygon.size(); ++i)
        if (polygon[i] == polygon[(i + 1) % polygon.size()]) return false;
    std::vector<Point> outline = points(polygon);
    return CGAL::is_simple_2(outline.begin(), outline.end(), Kernel());
}

}  // namespace veduta
