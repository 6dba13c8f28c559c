// Schrader's Spatial Landmark Graph (digest-003 §2.1, thesis L984–1160): the one plan structure
// of every level from a city down to an apartment's rooms. Corner nodes make the outline,
// landmark nodes on it send a ray inwards, inner nodes are where the rays cross; edges join
// them and carry what lies beyond (EdgeLocation); paths are closed loops of edges, and the
// faces a subdivision selects are paths. Edges are stored with a direction but the graph is
// walked in both, as the thesis's Listing 1 does; unlike Listing 1 each node keeps its edges,
// so a walk costs the edges it passes, not all of them each step.
#pragma once

#include <cstdint>
#include <vector>

#include "slg/edge_location.h"
#include "slg/plan_geometry.h"

namespace veduta {

using SlgNodeId = uint32_t;
using SlgEdgeId = uint32_t;
inline constexpr uint32_t kNoSlgId = UINT32_MAX;

enum class SlgNodeType : uint8_t { Corner, Inner, Landmark };

struct SlgNode {
    Vec2d position;
    SlgNodeType type = SlgNodeType::Corner;
    Vec2d ray;            // landmarks: the unit direction perpendicular into the outline
    bool reflex = false;  // corners: the outline turns right here (a concave corner)
    std::vector<SlgEdgeId> edges;
};

struct SlgEdge {
    SlgNodeId start = kNoSlgId, end = kNoSlgId;
    EdgeLocation location = EdgeLocation::Street;
    bool outer = false;  // on the outline; an inner edge has at least one inner node
    bool removed = false;
    SlgNodeId other(SlgNodeId n) const { return n == start ? end : start; }
    bool touches(SlgNodeId n) const { return n == start || n == end; }
};

// A closed loop: edges[i] joins nodes[i] and nodes[i + 1 mod n] (eq 3).
struct SlgPath {
    std::vector<SlgNodeId> nodes;
    std::vector<SlgEdgeId> edges;
};

enum class SlgPathType : uint8_t { Inner, Border, BorderWithCorner, BorderWithConcaveCorner };

class SlgGraph {
  public:
    SlgNodeId addNode(Vec2d position, SlgNodeType type, Vec2d ray = {});
    void markReflex(SlgNodeId n) { nodes_.at(n).reflex = true; }
    SlgEdgeId addEdge(SlgNodeId start, SlgNodeId end, EdgeLocation location, bool outer);
    // The edge between two nodes, if there is one that is not removed.
    SlgEdgeId edgeBetween(SlgNodeId a, SlgNodeId b) const;
    // Deleting an edge keeps its nodes (the thesis's footnote 30).
    void removeEdge(SlgEdgeId e);
    // Level rules (§2.2 step 7) and the plan extension's replacement (L1981): what lies beyond
    // an edge, or a piece of a wall that becomes a door or a window.
    void relabel(SlgEdgeId e, EdgeLocation location) { edges_.at(e).location = location; }

    // Eq 26: cuts edge e at start + (end − start)·t, 0 < t < 1. Edge e keeps its start and ends
    // at the new node; a new edge with e's location runs on to e's old end. Returns the node.
    SlgNodeId splitEdge(SlgEdgeId e, double t, SlgNodeType type, Vec2d ray = {});
    // Eq 14–15: when edge e and edge next meet at a node of no other edge and run in one
    // direction, e is extended over next and next removed. Returns whether it merged.
    bool mergeCollinear(SlgEdgeId e, SlgEdgeId next);

    const SlgNode &node(SlgNodeId n) const { return nodes_.at(n); }
    const SlgEdge &edge(SlgEdgeId e) const { return edges_.at(e); }
    const std::vector<SlgNode> &nodes() const { return nodes_; }
    const std::vector<SlgEdge> &edges() const { return edges_; }
    Vec2d position(SlgNodeId n) const { return nodes_.at(n).position; }
    // The vector along e from `from` to its other node.
    Vec2d along(SlgEdgeId e, SlgNodeId from) const;

    Polygon2d polygon(const SlgPath &path) const;
    SlgPathType pathType(const SlgPath &path) const;

  private:
    std::vector<SlgNode> nodes_;
    std::vector<SlgEdge> edges_;
};

// §4.6.1: turns a closed loop so that it runs counter-clockwise (positive signed area), the
// front-face winding of everything after.
void orderCounterClockwise(const SlgGraph &graph, SlgPath &path);

// Brings a path up to date after edges of it were split (eq 26): each edge is replaced by its
// pieces, in the path's direction, so the faces that share a split wall all see its new nodes.
void followSplits(const SlgGraph &graph, SlgPath &path);

// The graph of a counter-clockwise outline: a corner node for each point, in order, and outer
// edges from each to the next with the given locations, one per edge (eq 4).
SlgGraph outlineGraph(const Polygon2d &outline, const std::vector<EdgeLocation> &locations);

}  // namespace veduta
