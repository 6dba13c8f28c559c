// The blocks of a street network (Goitowski 2010's Parzellen, L1566–1573: the areas a street
// encloses with nothing inside but dead ends) as the bounded faces of the plane graph of its
// streets, found twice: by CGAL's Arrangement_2, and by a walk around every face with
// angle-sorted neighbours, the essence of the thesis' optimized cycle search (§4.3.2,
// L2925–2989, digest §3.1). docs/street-blocks.md documents what a block is and every choice.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace veduta {

// A point of the ground plane.
struct PlanarPoint {
    double x = 0, y = 0;
};

// An undirected street between two points, by their indices.
using PlanarEdge = std::pair<uint32_t, uint32_t>;

struct StreetBlock {
    // Point indices, counter-clockwise, starting at the smallest; dead ends left out.
    std::vector<uint32_t> boundary;
    // Inner boundaries (loops of streets inside the block), each clockwise from its smallest
    // index, in lexicographic order.
    std::vector<std::vector<uint32_t>> holes;
    double area = 0;  // of the boundary less the holes
    bool operator==(const StreetBlock &) const = default;
};

struct BlockResult {
    std::vector<StreetBlock> blocks;  // ordered by boundary, lexicographically
    // Bounded faces left out because their boundary (less dead ends) passes a point twice.
    size_t nonSimpleFaces = 0;
    // Edges joining a point to itself or to a copy of it, or repeating an earlier edge.
    size_t ignoredEdges = 0;
    // Points no kept edge ends at: isolated ones, and copies of an earlier point's coordinates
    // (their edges are moved to that point).
    size_t ignoredPoints = 0;
    // Only blocksByArrangement sees edges that cross, overlap or touch another's interior,
    // which the input promises not to have: its edges that are no input edge, and the bounded
    // faces left out because they have such an edge or a point that is no input point.
    size_t unmatchedEdges = 0;
    size_t invalidFaces = 0;
};

// More points or edges than this are refused.
inline constexpr size_t kMaxBlockGraphSize = 10'000'000;

// The input is a plane straight-line graph: edges meet only at their end points. Both throw
// std::invalid_argument for more than kMaxBlockGraphSize points or edges, an edge index
// without a point, and a coordinate that is not finite, larger than 1e100 in magnitude or a
// nonzero one below 1e-100 (where the face walk's exact predicates would underflow).
BlockResult blocksByArrangement(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges);
BlockResult blocksByFaceWalk(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges);

}  // namespace veduta
