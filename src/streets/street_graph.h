// The geometric street network the growth draws into (Goitowski 2010, §4.2.6–4.2.7, digest
// §2.6–2.7): street ends and crossings as vertices, streets as undirected straight edges, and
// the look-ups by area that the local constraints need. The word graph (word_graph.h) says what
// the rules wrote; this graph says what was built, cycles included.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

using VertexId = uint32_t;
using EdgeId = uint32_t;
inline constexpr VertexId kNoVertex = UINT32_MAX;

struct StreetVertex {
    Vec3f position;
    // Static vertices (an edge split, an existing road seeded into the graph) are what the
    // growth found, not what it drew: the thesis never moves or unhooks them.
    bool isStatic = false;
    std::vector<EdgeId> edges;  // in the order they were added
};

struct StreetEdge {
    VertexId a = kNoVertex, b = kNoVertex;
    VertexId other(VertexId v) const { return v == a ? b : a; }
};

class StreetGraph {
  public:
    // `cellSize` is the side of the squares the look-ups are bucketed by: near the typical edge
    // length, each look-up touches a few cells.
    explicit StreetGraph(float cellSize = 16);

    VertexId addVertex(const Vec3f &position, bool isStatic = false);
    // Joins two distinct vertices; joining a pair already joined returns their edge.
    EdgeId addEdge(VertexId a, VertexId b);
    // Cuts edge e at `point` (between its ends): e keeps its first vertex and ends at the new,
    // static vertex, and a new edge runs from there to e's old second vertex.
    VertexId splitEdge(EdgeId e, const Vec3f &point);

    const StreetVertex &vertex(VertexId v) const { return vertices_.at(v); }
    const StreetEdge &edge(EdgeId e) const { return edges_.at(e); }
    const std::vector<StreetVertex> &vertices() const { return vertices_; }
    const std::vector<StreetEdge> &edges() const { return edges_; }
    // The edge joining a and b, if any.
    EdgeId edgeBetween(VertexId a, VertexId b) const;

    // The vertices and edges that may lie within `pad` of the segment from p to q in the ground
    // plane (z ignored), each once, in increasing id: a superset the caller tests exactly.
    std::vector<VertexId> verticesNear(const Vec3f &p, const Vec3f &q, float pad) const;
    std::vector<EdgeId> edgesNear(const Vec3f &p, const Vec3f &q, float pad) const;

  private:
    using Cells = std::unordered_map<uint64_t, std::vector<uint32_t>>;
    // Calls visit(key) for each cell within `pad` of the segment: per column of cells, the rows
    // the segment crosses there. So a long street costs its length in cells, not its box's area.
    template <typename Visit>
    void forEachCell(const Vec3f &p, const Vec3f &q, float pad, Visit visit) const;
    void addToCells(Cells &cells, EdgeId e);
    void removeFromCells(Cells &cells, EdgeId e);
    std::vector<uint32_t> gather(const Cells &cells, const Vec3f &p, const Vec3f &q, float pad) const;

    float cellSize_;
    std::vector<StreetVertex> vertices_;
    std::vector<StreetEdge> edges_;
    Cells vertexCells_, edgeCells_;
};

}  // namespace veduta
