#include "streets/street_graph.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace veduta {

namespace {

uint64_t cellKey(int64_t x, int64_t y) { return (uint64_t(uint32_t(int32_t(x))) << 32) | uint32_t(int32_t(y)); }

// Clamped far beyond any town, so that a cell index always fits.
int64_t cellIndex(double coordinate, double cellSize) {
    return int64_t(std::clamp(std::floor(coordinate / cellSize), -1e9, 1e9));
}

}  // namespace

StreetGraph::StreetGraph(float cellSize) : cellSize_(cellSize) {
    if (!(cellSize > 0)) throw std::invalid_argument("the street graph's cell size must be positive");
}

VertexId StreetGraph::addVertex(const Vec3f &position, bool isStatic) {
    VertexId v = VertexId(vertices_.size());
    vertices_.push_back({position, isStatic, {}});
    forEachCell(position, position, 0, [&](uint64_t key) { vertexCells_[key].push_back(v); });
    return v;
}

EdgeId StreetGraph::addEdge(VertexId a, VertexId b) {
    if (a == b || a >= vertices_.size() || b >= vertices_.size())
        throw std::invalid_argument("an edge joins two distinct vertices of the graph");
    if (EdgeId existing = edgeBetween(a, b); existing != UINT32_MAX) return existing;
    EdgeId e = EdgeId(edges_.size());
    edges_.push_back({a, b});
    vertices_[a].edges.push_back(e);
    vertices_[b].edges.push_back(e);
    addToCells(edgeCells_, e);
    return e;
}

VertexId StreetGraph::splitEdge(EdgeId e, const Vec3f &point) {
    StreetEdge old = edges_.at(e);
    removeFromCells(edgeCells_, e);
    VertexId middle = addVertex(point, true);
    EdgeId rest = EdgeId(edges_.size());
    edges_[e].b = middle;
    edges_.push_back({middle, old.b});
    std::ranges::replace(vertices_[old.b].edges, e, rest);
    vertices_[middle].edges = {e, rest};
    addToCells(edgeCells_, e);
    addToCells(edgeCells_, rest);
    return middle;
}

EdgeId StreetGraph::edgeBetween(VertexId a, VertexId b) const {
    for (EdgeId e : vertices_.at(a).edges)
        if (edges_[e].other(a) == b) return e;
    return UINT32_MAX;
}

std::vector<VertexId> StreetGraph::verticesNear(const Vec3f &p, const Vec3f &q, float pad) const {
    return gather(vertexCells_, p, q, pad);
}

std::vector<EdgeId> StreetGraph::edgesNear(const Vec3f &p, const Vec3f &q, float pad) const {
    return gather(edgeCells_, p, q, pad);
}

template <typename Visit>
void StreetGraph::forEachCell(const Vec3f &p, const Vec3f &q, float pad, Visit visit) const {
    double x0 = std::min(p.x, q.x), x1 = std::max(p.x, q.x);
    for (int64_t column = cellIndex(x0 - pad, cellSize_); column <= cellIndex(x1 + pad, cellSize_); ++column) {
        // The part of the segment within `pad` of the column, and the rows it spans.
        double from = std::max(x0, column * double(cellSize_) - pad);
        double to = std::min(x1, (column + 1) * double(cellSize_) + pad);
        double dx = double(q.x) - p.x;
        auto yAt = [&](double x) { return dx == 0 ? double(p.y) : p.y + (q.y - double(p.y)) * ((x - p.x) / dx); };
        double ya = dx == 0 ? std::min(p.y, q.y) : std::min(yAt(from), yAt(to));
        double yb = dx == 0 ? std::max(p.y, q.y) : std::max(yAt(from), yAt(to));
        for (int64_t row = cellIndex(ya - pad, cellSize_); row <= cellIndex(yb + pad, cellSize_); ++row)
            visit(cellKey(column, row));
    }
}

void StreetGraph::addToCells(Cells &cells, EdgeId e) {
    const StreetEdge &edge = edges_[e];
    forEachCell(vertices_[edge.a].position, vertices_[edge.b].position, 0,
                [&](uint64_t key) { cells[key].push_back(e); });
}

void StreetGraph::removeFromCells(Cells &cells, EdgeId e) {
    const StreetEdge &edge = edges_[e];
    forEachCell(vertices_[edge.a].position, vertices_[edge.b].position, 0,
                [&](uint64_t key) { std::erase(cells[key], e); });
}

std::vector<uint32_t> StreetGraph::gather(const Cells &cells, const Vec3f &p, const Vec3f &q, float pad) const {
    std::vector<uint32_t> found;
    forEachCell(p, q, pad, [&](uint64_t key) {
        if (auto it = cells.find(key); it != cells.end())
            found.insert(found.end(), it->second.begin(), it->second.end());
    });
    std::ranges::sort(found);
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

}  // namespace veduta
