// Pieces of a block while it is cut into lots: which of their edges face a street, and cuts
// along a line with CGAL's exact Boolean operations. Shared by the recursive, OBB and
// straight-skeleton subdivisions (docs/lots.md).
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <vector>

#include "city/lot_subdivision.h"
#include "core/vecmath.h"

namespace veduta::lots {

// A simple counter-clockwise polygon in float, edge i from point i to point i + 1.
using Piece = std::vector<Vec2f>;

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;

ExactPolygon toExact(const Piece &piece);
// Rounded to float, with points that rounding merged dropped.
Piece toPiece(const ExactPolygon &polygon);

// A line through `on` running along the unit vector (dx, dy), in double.
struct CutLine {
    Vec2f on;
    double dx = 0, dy = 0;
};

// One flag per edge of `piece`: whether the edge lies along a street edge of the block (both its
// ends within a millimetre of the same street edge: float rounding of exact cut points).
std::vector<bool> streetFlags(const Piece &piece, const Block &block);
bool hasStreetEdge(const Piece &piece, const Block &block);

// The parts of `piece` left of `line` and right of it; a concave piece may give more than one
// on a side. Parts that rounding to float leaves with fewer than three points are dropped.
struct CutSides {
    std::vector<Piece> left, right;
};
CutSides cutPiece(const Piece &piece, const CutLine &line);

}  // namespace veduta::lots
