#include "city/ground_environment.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geo/height_queries.h"

namespace veduta {

namespace {

// Even-odd: whether `p` lies inside the ring.
bool inside(const LocalPolygon &ring, const Vec2d &p) {
    bool in = false;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Vec2d &a = ring[i], &b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

}  // namespace

GroundEnvironment::GroundEnvironment(const HeightGrid *grid, const LocalFrame &frame,
                                     std::vector<LocalPolygon> obstacles, Vec2d centre, GroundLimits limits) :
    grid_(grid), frame_(frame), obstacles_(std::move(obstacles)), centre_(centre), limits_(limits) {
    for (const LocalPolygon &ring : obstacles_) {
        Vec2d low = ring.front(), high = ring.front();
        for (const Vec2d &p : ring) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y)};
        }
        boxes_.emplace_back(low, high);
    }
}

bool GroundEnvironment::inObstacle(const Vec2d &p) const {
    for (size_t i = 0; i < obstacles_.size(); ++i) {
        const auto &[low, high] = boxes_[i];
        if (p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y && inside(obstacles_[i], p)) return true;
    }
    return false;
}

std::optional<double> GroundEnvironment::heightAt(const Vec2d &p) const {
    return bilinearHeight(*grid_, {frame_.origin.easting + p.x, frame_.origin.northing + p.y});
}

float GroundEnvironment::freeLength(const Vec3f &start, const Vec3f &direction, float length) const {
    Vec2d from{centre_.x + start.x, centre_.y + start.y};
    double planar = std::hypot(double(direction.x), double(direction.y));
    if (planar == 0 || length <= 0) return length;
    auto at = [&](double t) { return Vec2d{from.x + direction.x * t, from.y + direction.y * t}; };
    std::optional<double> height = grid_ ? heightAt(from) : std::optional<double>(0);
    if (!height || inObstacle(from)) return 0;
    int steps = std::max(1, int(std::ceil(length * planar / limits_.step)));
    double stride = double(length) / steps;
    for (int k = 1; k <= steps; ++k) {
        Vec2d p = at(k * stride);
        std::optional<double> next = grid_ ? heightAt(p) : height;
        bool tooSteep = next && std::abs(*next - *height) > limits_.maxGrade * stride * planar;
        if (!next || tooSteep || inObstacle(p)) return float((k - 1) * stride);
        height = next;
    }
    return length;
}

std::vector<LocalPolygon> streetObstacles(const std::vector<AtkisObject> &objects, const LocalFrame &frame) {
    std::vector<LocalPolygon> obstacles;
    for (const AtkisObject &o : objects) {
        LandClass c = landClass(o);
        if (o.geometry != AtkisGeometry::Area ||
            (c != LandClass::Water && c != LandClass::River && c != LandClass::Forest))
            continue;
        for (const MapRing &ring : o.areas) {
            if (ring.size() < 3) continue;
            LocalPolygon local;
            for (const MapPoint &p : ring)
                local.push_back({p.easting - frame.origin.easting, p.northing - frame.origin.northing});
            obstacles.push_back(std::move(local));
        }
    }
    return obstacles;
}

namespace {

// The part of the segment from p to q within `reach` of the origin, as parameters t0 < t1 of
// p + t (q − p) in [0, 1]; none when it misses the circle.
std::optional<std::pair<double, double>> withinReach(Vec2d p, Vec2d q, double reach) {
    Vec2d d{q.x - p.x, q.y - p.y};
    double a = d.x * d.x + d.y * d.y, b = 2 * (p.x * d.x + p.y * d.y), c = p.x * p.x + p.y * p.y - reach * reach;
    if (a == 0) return c <= 0 ? std::optional(std::pair(0.0, 1.0)) : std::nullopt;
    double disc = b * b - 4 * a * c;
    if (disc < 0) return std::nullopt;
    double t0 = std::max(0.0, (-b - std::sqrt(disc)) / (2 * a)), t1 = std::min(1.0, (-b + std::sqrt(disc)) / (2 * a));
    if (t0 >= t1) return std::nullopt;
    return std::pair(t0, t1);
}

}  // namespace

std::vector<std::vector<Vec2f>> roadsInWindow(const std::vector<std::vector<Vec2d>> &lines, Vec2d centre,
                                              double reach) {
    std::vector<std::vector<Vec2f>> roads;
    for (const std::vector<Vec2d> &line : lines) {
        std::vector<Vec2f> run;
        auto flush = [&] {
            if (run.size() >= 2) roads.push_back(run);
            run.clear();
        };
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            Vec2d p{line[i].x - centre.x, line[i].y - centre.y}, q{line[i + 1].x - centre.x, line[i + 1].y - centre.y};
            std::optional<std::pair<double, double>> inside = withinReach(p, q, reach);
            if (!inside) {
                flush();
                continue;
            }
            auto at = [&](double t) { return Vec2f{float(p.x + t * (q.x - p.x)), float(p.y + t * (q.y - p.y))}; };
            if (inside->first > 0) flush();  // it comes in across the edge of the window
            if (run.empty()) run.push_back(at(inside->first));
            run.push_back(at(inside->second));
            if (inside->second < 1) flush();  // and leaves it
        }
        flush();
    }
    return roads;
}

std::vector<std::vector<Vec2d>> streetLines(const CityData &data) {
    std::vector<std::vector<Vec2d>> lines;
    for (const CityStreet &s : data.streets)
        lines.push_back(
            {{data.points[s.start].e, data.points[s.start].n}, {data.points[s.end].e, data.points[s.end].n}});
    return lines;
}

std::vector<std::vector<Vec2f>> existingRoads(const std::vector<AtkisObject> &objects, const LocalFrame &frame,
                                              Vec2d centre, double reach) {
    std::vector<std::vector<Vec2d>> lines;
    for (const AtkisObject &o : objects) {
        if (o.geometry != AtkisGeometry::Line || landClass(o) != LandClass::Road) continue;
        for (const MapLine &line : o.lines) {
            std::vector<Vec2d> &local = lines.emplace_back();
            for (const MapPoint &m : line)
                local.push_back({m.easting - frame.origin.easting, m.northing - frame.origin.northing});
        }
    }
    return roadsInWindow(lines, centre, reach);
}

}  // namespace veduta
