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
    std::vector<SlgNodeId> landmarks;
    for (SlgEdgeId e = 0; e < corners; ++e) {
        SlgNodeId start = graph.edge(e).start, end = graph.edge(e).end;
        Vec2d inwards = normalized(leftNormal(graph.along(e, start)));
        std::vector<double> t = landmarkPositions(perEdge[e], lengths[e], parameters.jitter, graph.node(start).reflex,
                                                  graph.node(end).reflex, pull, random, e);
        // Each split leaves the rest of the edge as the newest edge; its fraction is rescaled.
        SlgEdgeId rest = e;
        double done = 0;
        for (double at : t) {
            landmarks.push_back(graph.splitEdge(rest, (at - done) / (1 - done), SlgNodeType::Landmark, inwards));
            rest = SlgEdgeId(graph.edges().size() - 1);
            done = at;
        }
    }
    return landmarks;
}

}  // namespace veduta
