#include "streets/street_constraints.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

namespace veduta {

namespace {

struct Ground {
    double x = 0, y = 0;
};

Ground operator-(Ground a, Ground b) { return {a.x - b.x, a.y - b.y}; }
Ground operator+(Ground a, Ground b) { return {a.x + b.x, a.y + b.y}; }
Ground operator*(Ground a, double s) { return {a.x * s, a.y * s}; }
double dot(Ground a, Ground b) { return a.x * b.x + a.y * b.y; }
double cross(Ground a, Ground b) { return a.x * b.y - a.y * b.x; }
double norm(Ground a) { return std::hypot(a.x, a.y); }
Ground unit(Ground a) { return a * (1 / norm(a)); }
Ground ground(const Vec3f &p) { return {p.x, p.y}; }

// Where a ray from `from` along unit `along` first meets the segment a–b: the distance along
// the ray and the fraction of the way from a to b. A segment lying on the ray meets it at its
// nearer end.
std::optional<std::pair<double, double>> rayHit(Ground from, Ground along, double reach, Ground a, Ground b) {
    Ground ab = b - a, fa = a - from;
    double denominator = cross(along, ab);
    if (std::abs(denominator) < 1e-12 * norm(ab)) {
        if (std::abs(cross(along, fa)) > 1e-9 * std::max(1.0, norm(fa))) return std::nullopt;  // parallel
        double ta = dot(fa, along), tb = dot(b - from, along);
        double t = std::min(ta, tb);
        if (t < 0 || t > reach) return std::nullopt;
        return std::pair(t, ta <= tb ? 0.0 : 1.0);
    }
    double t = cross(fa, ab) / denominator, r = cross(fa, along) / denominator;
    if (t < 0 || t > reach || r < 0 || r > 1) return std::nullopt;
    return std::pair(t, r);
}

class Planner {
  public:
    Planner(const StreetGraph &graph, const SegmentStart &start, const Vec3f &direction, float length,
            const StreetConstraints &constraints) :
        graph_(graph), constraints_(constraints), startId_(start.vertex), start_(start.position) {
        Ground flat{direction.x, direction.y};
        double flatLength = norm(flat);
        along_ = unit(flat);
        double full = std::sqrt(flatLength * flatLength + double(direction.z) * direction.z);
        reach_ = length * flatLength / full;
        slope_ = direction.z / flatLength;
        proposedEnd_ = start_ + normalize(direction) * length;
        cosMinAngle_ = std::cos(double(radians(constraints.minAngleDegrees)));
    }

    SegmentPlan plan() const {
        if (std::optional<SegmentPlan> snapped = snapToVertex()) return *snapped;
        return clipAtStreet();
    }

  private:
    double heightAt(double distance) const { return start_.z + slope_ * distance; }
    bool sameLevel(double a, double b) const { return std::abs(a - b) <= constraints_.heightTolerance; }

    // Every street at `v` leaves it at least minAngle away from the new one heading `towards`.
    bool anglesFit(VertexId v, Ground towards) const {
        if (v == kNoVertex) return true;
        Ground from = ground(graph_.vertex(v).position);
        for (EdgeId e : graph_.vertex(v).edges) {
            Ground street = unit(ground(graph_.vertex(graph_.edge(e).other(v)).position) - from);
            if (dot(street, towards) > cosMinAngle_) return false;
        }
        return true;
    }

    // A street from the start to vertex v would meet no street but those at its two ends.
    bool clearTo(VertexId v) const {
        const Vec3f &end = graph_.vertex(v).position;
        Ground from = ground(start_), direction = ground(end) - from;
        double reach = norm(direction);
        direction = direction * (1 / reach);
        for (EdgeId e : graph_.edgesNear(start_, end, 1e-3f)) {
            const StreetEdge &edge = graph_.edge(e);
            if (edge.a == startId_ || edge.b == startId_ || edge.a == v || edge.b == v) continue;
            const Vec3f &a = graph_.vertex(edge.a).position, &b = graph_.vertex(edge.b).position;
            auto hit = rayHit(from, direction, reach, ground(a), ground(b));
            if (!hit) continue;
            double height = start_.z + (end.z - start_.z) * (hit->first / reach);
            if (sameLevel(height, a.z + (b.z - a.z) * hit->second)) return false;
        }
        return true;
    }

    // A plan ending at an existing vertex, if the length, the angles at both ends and the way
    // there allow it.
    std::optional<SegmentPlan> toVertex(VertexId v, QueryResult code) const {
        const Vec3f &end = graph_.vertex(v).position;
        Ground way = ground(end) - ground(start_);
        double distance = norm(way);
        bool joined = startId_ != kNoVertex && graph_.edgeBetween(startId_, v) != UINT32_MAX;
        if (distance < constraints_.minLength || joined) return std::nullopt;
        way = way * (1 / distance);
        if (!anglesFit(startId_, way) || !anglesFit(v, way * -1) || !clearTo(v)) return std::nullopt;
        SegmentPlan plan{code, SegmentTarget::Vertex, end, v};
        plan.length = ::veduta::length(end - start_);
        plan.turnDegrees = -float(std::atan2(cross(along_, way), dot(along_, way)) * 180 / std::numbers::pi);
        return plan;
    }

    // The nearest-neighbour test: the vertices in the hull that runs from the start to `width`
    // past the proposed end, `width` to either side, the nearest to the end first.
    std::optional<SegmentPlan> snapToVertex() const {
        double width = constraints_.snapFraction * reach_;
        Ground from = ground(start_);
        Vec3f hullEnd = start_ + Vec3f(float(along_.x), float(along_.y), 0) * float(reach_ + width);
        std::vector<std::pair<double, VertexId>> inHull;
        for (VertexId v : graph_.verticesNear(start_, hullEnd, float(width))) {
            if (v == startId_) continue;
            const Vec3f &p = graph_.vertex(v).position;
            Ground offset = ground(p) - from;
            double t = dot(offset, along_);
            if (t <= 0 || t > reach_ + width || std::abs(cross(along_, offset)) > width) continue;
            if (!sameLevel(p.z, heightAt(t))) continue;
            inHull.emplace_back(norm(ground(p) - ground(proposedEnd_)), v);
        }
        std::ranges::sort(inHull);
        for (auto [distance, v] : inHull)
            if (auto plan = toVertex(v, QueryResult::NearestNeighbour)) return plan;
        return std::nullopt;
    }

    // The intersection test: the nearest street on the proposal extended by collisionOffset.
    SegmentPlan clipAtStreet() const {
        double reach = reach_ + constraints_.collisionOffset;
        Ground from = ground(start_);
        Vec3f far = start_ + Vec3f(float(along_.x), float(along_.y), 0) * float(reach);
        std::optional<std::tuple<double, EdgeId, double>> nearest;  // distance, edge, fraction
        for (EdgeId e : graph_.edgesNear(start_, far, 1e-3f)) {
            const StreetEdge &edge = graph_.edge(e);
            if (edge.a == startId_ || edge.b == startId_) continue;
            const Vec3f &a = graph_.vertex(edge.a).position, &b = graph_.vertex(edge.b).position;
            auto hit = rayHit(from, along_, reach, ground(a), ground(b));
            if (!hit || !sameLevel(heightAt(hit->first), a.z + (b.z - a.z) * hit->second)) continue;
            if (!nearest || std::pair(hit->first, e) < std::pair(std::get<0>(*nearest), std::get<1>(*nearest)))
                nearest = std::tuple(hit->first, e, hit->second);
        }
        if (!nearest) return proposed();
        auto [distance, e, fraction] = *nearest;
        QueryResult code = distance > reach_ ? QueryResult::ForwardIntersection : QueryResult::Intersection;
        return meetStreet(e, distance, fraction, code);
    }

    // Met street e at `distance`: cut it there, or, where a piece of it would stay shorter than
    // minLength, go to its end instead (the thesis' redirect).
    SegmentPlan meetStreet(EdgeId e, double distance, double fraction, QueryResult code) const {
        const StreetEdge &edge = graph_.edge(e);
        const Vec3f &a = graph_.vertex(edge.a).position, &b = graph_.vertex(edge.b).position;
        Ground street = ground(b) - ground(a);
        double streetLength = norm(street);
        double toA = fraction * streetLength, toB = (1 - fraction) * streetLength;
        if (std::min(toA, toB) < constraints_.minLength)
            return toVertex(toA <= toB ? edge.a : edge.b, code).value_or(SegmentPlan{});
        bool steepEnough = std::abs(dot(unit(street), along_)) <= cosMinAngle_;
        if (distance < constraints_.minLength || !steepEnough || !anglesFit(startId_, along_)) return {};
        Ground hit = ground(start_) + along_ * distance;
        Vec3f end(float(hit.x), float(hit.y), float(a.z + (b.z - a.z) * fraction));
        SegmentPlan plan{code, SegmentTarget::EdgeSplit, end, kNoVertex, e};
        plan.length = ::veduta::length(end - start_);
        return plan;
    }

    SegmentPlan proposed() const {
        if (!anglesFit(startId_, along_)) return {};
        SegmentPlan plan{QueryResult::Normal, SegmentTarget::NewVertex, proposedEnd_};
        plan.length = ::veduta::length(proposedEnd_ - start_);
        return plan;
    }

    const StreetGraph &graph_;
    const StreetConstraints &constraints_;
    VertexId startId_;
    Vec3f start_, proposedEnd_;
    Ground along_;
    double reach_ = 0, slope_ = 0, cosMinAngle_ = 0;
};

}  // namespace

SegmentPlan planSegment(const StreetGraph &graph, const SegmentStart &start, const Vec3f &direction, float length,
                        const StreetConstraints &constraints) {
    double flat = std::hypot(double(direction.x), double(direction.y));
    double full = std::sqrt(flat * flat + double(direction.z) * direction.z);
    const Vec3f &from = start.position;
    bool finite = std::isfinite(full) && std::isfinite(from.x) && std::isfinite(from.y) && std::isfinite(from.z);
    if (!(length >= constraints.minLength && length <= constraints.maxLength) || !(full > 0) || !finite) return {};
    // A lift between levels has no extent in the ground plane the tests work in: it goes as proposed.
    if (flat < 1e-3 * full) {
        Vec3f end = start.position + normalize(direction) * length;
        SegmentPlan plan{QueryResult::Normal, SegmentTarget::NewVertex, end};
        plan.length = length;
        return plan;
    }
    if (length * flat / full < constraints.minLength) return {};
    return Planner(graph, start, direction, length, constraints).plan();
}

}  // namespace veduta
