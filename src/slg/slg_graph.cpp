#include "slg/slg_graph.h"

#include <algorithm>

#include "core/check.h"

namespace veduta {

SlgNodeId SlgGraph::addNode(Vec2d position, SlgNodeType type, Vec2d ray) {
    nodes_.push_back({position, type, ray, false, {}});
    return SlgNodeId(nodes_.size() - 1);
}

SlgEdgeId SlgGraph::addEdge(SlgNodeId start, SlgNodeId end, EdgeLocation location, bool outer) {
    VEDUTA_CHECK(start != end && start < nodes_.size() && end < nodes_.size(), "an SLG edge needs two distinct nodes");
    auto e = SlgEdgeId(edges_.size());
    edges_.push_back({start, end, location, outer, false});
    nodes_[start].edges.push_back(e);
    nodes_[end].edges.push_back(e);
    return e;
}

SlgEdgeId SlgGraph::edgeBetween(SlgNodeId a, SlgNodeId b) const {
    for (SlgEdgeId e : nodes_.at(a).edges)
        if (!edges_[e].removed && edges_[e].touches(b)) return e;
    return kNoSlgId;
}

void SlgGraph::removeEdge(SlgEdgeId e) {
    SlgEdge &edge = edges_.at(e);
    if (edge.removed) return;
    edge.removed = true;
    for (SlgNodeId n : {edge.start, edge.end}) std::erase(nodes_[n].edges, e);
}

SlgNodeId SlgGraph::splitEdge(SlgEdgeId e, double t, SlgNodeType type, Vec2d ray) {
    VEDUTA_CHECK(t > 0 && t < 1 && !edges_.at(e).removed, "an SLG edge is split strictly between its ends");
    SlgEdge old = edges_[e];
    Vec2d p = nodes_[old.start].position;
    SlgNodeId middle = addNode(p + (nodes_[old.end].position - p) * t, type, ray);
    std::erase(nodes_[old.end].edges, e);
    edges_[e].end = middle;
    nodes_[middle].edges.push_back(e);
    addEdge(middle, old.end, old.location, old.outer);
    return middle;
}

bool SlgGraph::mergeCollinear(SlgEdgeId e, SlgEdgeId next) {
    SlgEdge &first = edges_.at(e);
    const SlgEdge &second = edges_.at(next);
    if (first.removed || second.removed || e == next) return false;
    SlgNodeId joint = first.end;
    if (!second.touches(joint) || nodes_[joint].edges.size() != 2) return false;
    SlgNodeId far = second.other(joint);
    if (!goesStraightOn(nodes_[first.start].position, nodes_[joint].position, nodes_[far].position)) return false;
    removeEdge(next);
    std::erase(nodes_[joint].edges, e);
    first.end = far;
    nodes_[far].edges.push_back(e);
    return true;
}

Vec2d SlgGraph::along(SlgEdgeId e, SlgNodeId from) const {
    return nodes_[edges_.at(e).other(from)].position - nodes_.at(from).position;
}

Polygon2d SlgGraph::polygon(const SlgPath &path) const {
    Polygon2d points;
    points.reserve(path.nodes.size());
    for (SlgNodeId n : path.nodes) points.push_back(nodes_.at(n).position);
    return points;
}

SlgPathType SlgGraph::pathType(const SlgPath &path) const {
    size_t outerEdges = std::ranges::count_if(path.edges, [&](SlgEdgeId e) { return edges_[e].outer; });
    if (outerEdges == 0) return SlgPathType::Inner;
    bool corner = false, concave = false;
    for (SlgNodeId n : path.nodes) {
        if (nodes_[n].type != SlgNodeType::Corner) continue;
        corner = true;
        concave = concave || nodes_[n].reflex;
    }
    if (outerEdges < 2 || !corner) return SlgPathType::Border;
    return concave ? SlgPathType::BorderWithConcaveCorner : SlgPathType::BorderWithCorner;
}

void orderCounterClockwise(const SlgGraph &graph, SlgPath &path) {
    if (signedArea(graph.polygon(path)) >= 0) return;
    std::ranges::reverse(path.nodes);
    // edges[i] joined nodes[i] and nodes[i+1]; after reversing the nodes it must join the new
    // nodes[i] and nodes[i+1], which is old edge n−2−i (mod n).
    std::ranges::reverse(path.edges);
    std::rotate(path.edges.begin(), path.edges.begin() + 1, path.edges.end());
}

namespace {

// The pieces an edge of a path was split into, from `from` to `to`. A split keeps the edge's
// start, so the edge still touches one of the two; its pieces are joined by the split nodes,
// which have no other edges.
void appendPieces(const SlgGraph &graph, SlgEdgeId e, SlgNodeId from, SlgNodeId to, SlgPath &walked) {
    bool forward = graph.edge(e).touches(from);
    SlgNodeId node = forward ? from : to, goal = forward ? to : from;
    std::vector<SlgNodeId> nodes;
    std::vector<SlgEdgeId> edges;
    while (true) {
        nodes.push_back(node);
        edges.push_back(e);
        node = graph.edge(e).other(node);
        if (node == goal) break;
        const std::vector<SlgEdgeId> &joint = graph.node(node).edges;
        VEDUTA_CHECK(joint.size() == 2, "a split node of a path's edge joins only its two pieces");
        e = joint[0] == e ? joint[1] : joint[0];
    }
    if (!forward) {
        // Walked from `to`: the nodes must start at `from`, each edge following its start node.
        nodes.push_back(goal);
        std::ranges::reverse(nodes);
        nodes.pop_back();
        std::ranges::reverse(edges);
    }
    walked.nodes.insert(walked.nodes.end(), nodes.begin(), nodes.end());
    walked.edges.insert(walked.edges.end(), edges.begin(), edges.end());
}

}  // namespace

void followSplits(const SlgGraph &graph, SlgPath &path) {
    SlgPath walked;
    for (size_t i = 0; i < path.nodes.size(); ++i)
        appendPieces(graph, path.edges[i], path.nodes[i], path.nodes[(i + 1) % path.nodes.size()], walked);
    path = std::move(walked);
}

SlgGraph outlineGraph(const Polygon2d &outline, const std::vector<EdgeLocation> &locations) {
    VEDUTA_CHECK(outline.size() >= 3 && locations.size() == outline.size() && signedArea(outline) > 0,
                 "an SLG outline is counter-clockwise with a location per edge");
    SlgGraph graph;
    for (size_t i = 0; i < outline.size(); ++i) {
        SlgNodeId n = graph.addNode(outline[i], SlgNodeType::Corner);
        if (isReflexCorner(outline, i)) graph.markReflex(n);
    }
    for (size_t i = 0; i < outline.size(); ++i)
        graph.addEdge(SlgNodeId(i), SlgNodeId((i + 1) % outline.size()), locations[i], true);
    return graph;
}

}  // namespace veduta
