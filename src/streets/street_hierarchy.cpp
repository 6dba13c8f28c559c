#include "streets/street_hierarchy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <tuple>

namespace veduta {

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The ends of edges, as 2·edge + (0 at its first point, 1 at its second).
using EdgeEnd = uint32_t;

struct Direction {
    double x = 0, y = 0;
};

// The unit direction from the end's point along the edge; zero for an edge of no length.
Direction awayFrom(std::span<const PlanarPoint> points, const PlanarEdge &edge, bool atSecond) {
    const PlanarPoint &from = points[atSecond ? edge.second : edge.first];
    const PlanarPoint &to = points[atSecond ? edge.first : edge.second];
    double dx = to.x - from.x, dy = to.y - from.y, length = std::hypot(dx, dy);
    return length > 0 ? Direction{dx / length, dy / length} : Direction{};
}

// For each edge end, the end of the edge it continues into there, or kNone.
std::vector<uint32_t> continuations(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges,
                                    float continuationDegrees) {
    std::vector<std::vector<EdgeEnd>> endsAt(points.size());
    for (uint32_t e = 0; e < edges.size(); ++e) {
        if (edges[e].first == edges[e].second) continue;
        endsAt[edges[e].first].push_back(2 * e);
        endsAt[edges[e].second].push_back(2 * e + 1);
    }
    // Two edges continue one another when the angle between their directions away from the
    // vertex is at least 180° less the threshold: its cosine at most −cos(threshold).
    double limit = -std::cos(double(continuationDegrees) * std::numbers::pi / 180);
    std::vector<uint32_t> partner(2 * edges.size(), kNone);
    for (const std::vector<EdgeEnd> &ends : endsAt) {
        std::vector<std::tuple<double, EdgeEnd, EdgeEnd>> pairs;
        for (size_t i = 0; i < ends.size(); ++i) {
            Direction u = awayFrom(points, edges[ends[i] / 2], ends[i] % 2);
            for (size_t j = i + 1; j < ends.size(); ++j) {
                Direction v = awayFrom(points, edges[ends[j] / 2], ends[j] % 2);
                double cosine = u.x * v.x + u.y * v.y;
                bool degenerate = (u.x == 0 && u.y == 0) || (v.x == 0 && v.y == 0);
                if (!degenerate && cosine <= limit) pairs.emplace_back(cosine, ends[i], ends[j]);
            }
        }
        std::sort(pairs.begin(), pairs.end());
        for (const auto &[cosine, a, b] : pairs)
            if (partner[a] == kNone && partner[b] == kNone) partner[a] = b, partner[b] = a;
    }
    return partner;
}

// The edges a stroke runs through from `start`, leaving it by its end `exit`, as long as they
// are not in a stroke yet.
std::vector<uint32_t> follow(uint32_t exit, const std::vector<uint32_t> &partner, std::vector<bool> &taken) {
    std::vector<uint32_t> run;
    for (uint32_t next = partner[exit]; next != kNone && !taken[next / 2]; next = partner[next ^ 1]) {
        taken[next / 2] = true;
        run.push_back(next / 2);
    }
    return run;
}

double lengthOf(std::span<const PlanarPoint> points, const PlanarEdge &edge) {
    const PlanarPoint &a = points[edge.first], &b = points[edge.second];
    return std::hypot(b.x - a.x, b.y - a.y);
}

}  // namespace

std::vector<Stroke> strokesOf(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges,
                              float continuationDegrees) {
    std::vector<uint32_t> partner = continuations(points, edges, continuationDegrees);
    std::vector<bool> taken(edges.size(), false);
    std::vector<Stroke> strokes;
    for (uint32_t e = 0; e < edges.size(); ++e) {
        if (taken[e]) continue;
        taken[e] = true;
        std::vector<uint32_t> back = follow(2 * e, partner, taken);
        std::vector<uint32_t> ahead = follow(2 * e + 1, partner, taken);
        Stroke stroke(back.rbegin(), back.rend());
        stroke.push_back(e);
        stroke.insert(stroke.end(), ahead.begin(), ahead.end());
        strokes.push_back(std::move(stroke));
    }
    return strokes;
}

std::vector<StreetClass> classifyStreets(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges,
                                         const StreetHierarchy &hierarchy) {
    std::vector<Stroke> strokes = strokesOf(points, edges, hierarchy.continuationDegrees);
    std::vector<double> length(strokes.size(), 0);
    double total = 0;
    for (size_t s = 0; s < strokes.size(); ++s) {
        for (uint32_t e : strokes[s]) length[s] += lengthOf(points, edges[e]);
        total += length[s];
    }
    std::vector<size_t> order(strokes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return length[a] > length[b]; });
    std::vector<StreetClass> classes(edges.size(), StreetClass::Minor);
    double major = 0;
    for (size_t s : order) {
        if (major >= double(hierarchy.majorShare) * total) break;
        for (uint32_t e : strokes[s]) classes[e] = StreetClass::Major;
        major += length[s];
    }
    return classes;
}

}  // namespace veduta
