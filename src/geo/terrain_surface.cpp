#include "geo/terrain_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace veduta {

namespace {

constexpr double kParameterSlack = 1e-12;  // an edge crossing just past an end still counts

Vec2d plan(const Vec3f &p) { return {p.x, p.y}; }

// Even–odd; a point on the boundary may fall either way (the boundary crossings cover it).
bool inside(std::span<const Vec2d> polygon, Vec2d p) {
    bool in = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        Vec2d a = polygon[j], b = polygon[i];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
    }
    return in;
}

// Calls `found(point, height)` where the mesh edge p–q meets the polygon edge a–b; for
// collinear edges, at the mesh edge's ends that lie on a–b.
template <typename F>
void edgeCrossings(Vec2d a, Vec2d b, const Vec3f &p, const Vec3f &q, F &&found) {
    Vec2d r = (b - a), s = plan(q) - plan(p), ap = plan(p) - a;
    double denominator = cross(r, s);
    if (denominator != 0) {
        double t = cross(ap, s) / denominator, u = cross(ap, r) / denominator;
        if (t < -kParameterSlack || t > 1 + kParameterSlack || u < -kParameterSlack || u > 1 + kParameterSlack) return;
        u = std::clamp(u, 0.0, 1.0);
        found(Vec2d{p.x + u * s.x, p.y + u * s.y}, double(p.z) + u * (double(q.z) - double(p.z)));
    } else if (cross(ap, r) == 0 && (r.x != 0 || r.y != 0)) {
        double rr = r.x * r.x + r.y * r.y;
        for (const Vec3f *end : {&p, &q}) {
            double t = (double(end->x - a.x) * r.x + double(end->y - a.y) * r.y) / rr;
            if (t >= 0 && t <= 1) found(plan(*end), double(end->z));
        }
    }
}

std::vector<Vec2d> toDouble(std::span<const Vec2f> polygon) {
    std::vector<Vec2d> out;
    out.reserve(polygon.size());
    for (Vec2f p : polygon) out.push_back({p.x, p.y});
    return out;
}

}  // namespace

TerrainSurface::TerrainSurface(const Mesh &terrain, GridLines cellLines) :
    positions_(terrain.positions), indices_(terrain.indices), lines_(std::move(cellLines)) {
    if (positions_.empty() || indices_.empty()) return;
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const Vec3f &p : positions_) {
        x0 = std::min(x0, double(p.x)), y0 = std::min(y0, double(p.y));
        x1 = std::max(x1, double(p.x)), y1 = std::max(y1, double(p.y));
    }
    size_t triangles = indices_.size() / 3;
    if (lines_.xs.size() >= 2) {
        bucketSize_ = (lines_.xs.back() - lines_.xs.front()) / double(lines_.xs.size() - 1);
    } else {
        bucketSize_ = 2 * std::sqrt(std::max((x1 - x0) * (y1 - y0), 1e-12) / double(triangles));
    }
    // At most a few buckets per triangle, however the lines were chosen.
    double extent = std::max(x1 - x0, y1 - y0);
    bucketSize_ = std::max({bucketSize_, extent / 4096.0, 1e-9});
    originX_ = x0, originY_ = y0;
    bucketColumns_ = int((x1 - x0) / bucketSize_) + 1;
    bucketRows_ = int((y1 - y0) / bucketSize_) + 1;

    bucketStart_.assign(size_t(bucketColumns_) * size_t(bucketRows_) + 1, 0);
    auto forEachBucket = [&](size_t t, auto &&f) {
        const Vec3f &a = positions_[indices_[3 * t]], &b = positions_[indices_[3 * t + 1]],
                    &c = positions_[indices_[3 * t + 2]];
        int c0 = bucketColumn(std::min({a.x, b.x, c.x})), c1 = bucketColumn(std::max({a.x, b.x, c.x}));
        int r0 = bucketRow(std::min({a.y, b.y, c.y})), r1 = bucketRow(std::max({a.y, b.y, c.y}));
        for (int r = r0; r <= r1; ++r) {
            for (int col = c0; col <= c1; ++col) f(size_t(r) * size_t(bucketColumns_) + size_t(col));
        }
    };
    for (size_t t = 0; t < triangles; ++t) forEachBucket(t, [&](size_t k) { ++bucketStart_[k + 1]; });
    for (size_t k = 1; k < bucketStart_.size(); ++k) bucketStart_[k] += bucketStart_[k - 1];
    bucketTriangles_.resize(bucketStart_.back());
    std::vector<uint32_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
    for (size_t t = 0; t < triangles; ++t)
        forEachBucket(t, [&](size_t k) { bucketTriangles_[fill[k]++] = uint32_t(t); });
}

int TerrainSurface::bucketColumn(double x) const {
    return std::clamp(int(std::floor((x - originX_) / bucketSize_)), 0, bucketColumns_ - 1);
}

int TerrainSurface::bucketRow(double y) const {
    return std::clamp(int(std::floor((y - originY_) / bucketSize_)), 0, bucketRows_ - 1);
}

std::vector<uint32_t> TerrainSurface::trianglesNear(double x0, double y0, double x1, double y1) const {
    std::vector<uint32_t> found;
    if (bucketColumns_ == 0) return found;
    for (int r = bucketRow(y0); r <= bucketRow(y1); ++r) {
        for (int c = bucketColumn(x0); c <= bucketColumn(x1); ++c) {
            size_t k = size_t(r) * size_t(bucketColumns_) + size_t(c);
            found.insert(found.end(), bucketTriangles_.begin() + bucketStart_[k],
                         bucketTriangles_.begin() + bucketStart_[k + 1]);
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

std::optional<TerrainSurface::PointOnSurface> TerrainSurface::triangleAt(Vec2d p) const {
    constexpr double kSlack = 1e-9;  // barycentric: a point on an edge is in both triangles
    double bestMin = -std::numeric_limits<double>::infinity();
    PointOnSurface best;
    for (uint32_t t : trianglesNear(p.x, p.y, p.x, p.y)) {
        const Vec3f &a = positions_[indices_[3 * t]], &b = positions_[indices_[3 * t + 1]],
                    &c = positions_[indices_[3 * t + 2]];
        double d = (double(b.y) - c.y) * (double(a.x) - c.x) + (double(c.x) - b.x) * (double(a.y) - c.y);
        if (d == 0) continue;
        double la = ((double(b.y) - c.y) * (p.x - c.x) + (double(c.x) - b.x) * (p.y - c.y)) / d;
        double lb = ((double(c.y) - a.y) * (p.x - c.x) + (double(a.x) - c.x) * (p.y - c.y)) / d;
        double lc = 1 - la - lb;
        double lowest = std::min({la, lb, lc});
        if (lowest > bestMin) {
            bestMin = lowest;
            best.triangle = t;
            best.height = la * a.z + lb * b.z + lc * c.z;
        }
    }
    if (bestMin < -kSlack) return std::nullopt;
    return best;
}

std::optional<double> TerrainSurface::heightAt(Vec2d p) const {
    std::optional<PointOnSurface> on = triangleAt(p);
    return on ? std::optional<double>(on->height) : std::nullopt;
}

std::optional<double> TerrainSurface::extreme(std::span<const Vec2d> polygon, const HeightPlane &plane,
                                              double sign) const {
    if (polygon.empty()) return std::nullopt;
    double best = -std::numeric_limits<double>::infinity();
    auto consider = [&](Vec2d p, double height) { best = std::max(best, sign * (height - plane.at(p))); };
    double x0 = polygon[0].x, y0 = polygon[0].y, x1 = x0, y1 = y0;
    for (Vec2d p : polygon) {
        x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        if (std::optional<double> h = heightAt(p)) consider(p, *h);
    }
    for (uint32_t t : trianglesNear(x0, y0, x1, y1)) {
        for (size_t k = 0; k < 3; ++k) {
            const Vec3f &p = positions_[indices_[3 * t + k]], &q = positions_[indices_[3 * t + (k + 1) % 3]];
            if (polygon.size() >= 3 && inside(polygon, plan(p))) consider(plan(p), p.z);
            for (size_t i = 0; i < polygon.size(); ++i) {
                edgeCrossings(polygon[i], polygon[(i + 1) % polygon.size()], p, q, consider);
            }
        }
    }
    if (best == -std::numeric_limits<double>::infinity()) return std::nullopt;
    return sign * best;
}

std::optional<double> TerrainSurface::maxOver(std::span<const Vec2d> polygon) const { return extreme(polygon, {}, 1); }
std::optional<double> TerrainSurface::minOver(std::span<const Vec2d> polygon) const { return extreme(polygon, {}, -1); }
std::optional<double> TerrainSurface::maxOver(std::span<const Vec2f> polygon) const {
    return maxOver(toDouble(polygon));
}
std::optional<double> TerrainSurface::minOver(std::span<const Vec2f> polygon) const {
    return minOver(toDouble(polygon));
}

std::optional<double> TerrainSurface::maxAbove(std::span<const Vec2d> polygon, const HeightPlane &plane) const {
    return extreme(polygon, plane, 1);
}

}  // namespace veduta
