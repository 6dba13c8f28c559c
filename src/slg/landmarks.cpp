#include "slg/landmarks.h"

#include <algorithm>

#include "core/check.h"

namespace veduta {

std::vector<int> landmarksPerEdge(const std::vector<double> &lengths, int count) {
    std::vector<int> perEdge(lengths.size(), 0);
    for (int placed = 0; placed < count && !lengths.empty(); ++placed) {
        size_t best = 0;
        for (size_t i = 1; i < lengths.size(); ++i)
            if (lengths[i] / (perEdge[i] + 1) > lengths[best] / (perEdge[best] + 1)) best = i;
        ++perEdge[best];
    }
    return perEdge;
}

std::vector<double> landmarkPositions(int k, double length, double jitter, bool reflexStart, bool reflexEnd,
                                      double pull, const PlanRandom &random, uint32_t edgeIndex) {
    std::vector<double> t;
    double spacing = 1.0 / (k + 1);
    for (int i = 1; i <= k; ++i)
        t.push_back(i * spacing + spacing * random.uniform(-jitter, jitter, edgeIndex, uint32_t(i)));
    if (k == 0 || pull <= 0 || pull >= length) return t;
    double fromCorner = pull / length;
    if (reflexStart && (k == 1 || fromCorner < t[1])) t.front() = fromCorner;
    // A single landmark between two concave corners stays with the first.
    bool taken = k == 1 && reflexStart;
    double before = k >= 2 ? t[k - 2] : 0;
    if (reflexEnd && !taken && 1 - fromCorner > before) t.back() = 1 - fromCorner;
    return t;
}

namespace {

// Landmarks on opposite sides whose rays run a little apart make a jog shorter than length_min
// in the faces between them, and the selection drops those faces (a 12 m storey's third
// apartment, an apartment's rooms): eq 16's jitter is meant to vary the faces, not to break
// them. So a landmark facing one on an opposite, parallel edge (within kFacingTurn) across less
// than `closer` moves along its edge onto that one's ray, where that keeps its edge's order.
void alignFacingLandmarks(const Polygon2d &outline, const std::vector<double> &lengths,
                          std::vector<std::vector<double>> &t, double closer) {
    constexpr double kFacingTurn = 2;  // degrees
    size_t n = outline.size();
    auto direction = [&](size_t e) { return normalized(outline[(e + 1) % n] - outline[e]); };
    for (size_t e = 0; e < n; ++e) {
        for (size_t f = e + 1; f < n; ++f) {
            if (angle180(direction(e), direction(f)) < 180 - kFacingTurn) continue;
            Vec2d ray = leftNormal(direction(e));
            for (size_t j = 0; j < t[f].size(); ++j) {
                Vec2d at = outline[f] + direction(f) * (t[f][j] * lengths[f]);
                double offset = closer;
                for (double ti : t[e]) {
                    double d = cross(ray, at - (outline[e] + direction(e) * (ti * lengths[e])));
                    if (std::abs(d) < std::abs(offset)) offset = d;
                }
                if (offset == 0 || std::abs(offset) >= closer) continue;
                double moved = t[f][j] - offset / cross(ray, direction(f)) / lengths[f];
                double low = j > 0 ? t[f][j - 1] : 0, high = j + 1 < t[f].size() ? t[f][j + 1] : 1;
                double margin = closer / lengths[f];
                if (moved > low + margin && moved < high - margin) t[f][j] = moved;
            }
        }
    }
}

}  // namespace

std::vector<SlgNodeId> placeLandmarks(SlgGraph &graph, const PlanParameters &parameters, const PlanRandom &random) {
    size_t corners = graph.nodes().size();
    VEDUTA_CHECK(graph.edges().size() == corners, "placeLandmarks on a graph that is not a fresh outline");
    Polygon2d outline;
    std::vector<double> lengths;
    for (SlgEdgeId e = 0; e < corners; ++e) {
        outline.push_back(graph.position(graph.edge(e).start));
        lengths.push_back(length(graph.along(e, graph.edge(e).start)));
    }
    double perimeter = 0;
    for (double l : lengths) perimeter += l;
    int count = landmarkCount(parameters, signedArea(outline), perimeter, int(corners));
    if (count < 2) return {};

    std::vector<int> perEdge = landmarksPerEdge(lengths, count);
    double pull = lengthLimits(parameters).minimum;
    std::vector<std::vector<double>> t;
    for (SlgEdgeId e = 0; e < corners; ++e)
        t.push_back(landmarkPositions(perEdge[e], lengths[e], parameters.jitter, graph.node(graph.edge(e).start).reflex,
                                      graph.node(graph.edge(e).end).reflex, pull, random, e));
    alignFacingLandmarks(outline, lengths, t, pull);
    std::vector<SlgNodeId> landmarks;
    for (SlgEdgeId e = 0; e < corners; ++e) {
        Vec2d inwards = normalized(leftNormal(graph.along(e, graph.edge(e).start)));
        // Each split leaves the rest of the edge as the newest edge; its fraction is rescaled.
        SlgEdgeId rest = e;
        double done = 0;
        for (double at : t[e]) {
            landmarks.push_back(graph.splitEdge(rest, (at - done) / (1 - done), SlgNodeType::Landmark, inwards));
            rest = SlgEdgeId(graph.edges().size() - 1);
            done = at;
        }
    }
    return landmarks;
}

}  // namespace veduta
