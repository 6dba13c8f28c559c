// What every lot of every subdivision must be, shared by the lot tests: exact areas and
// overlaps with CGAL, street edges on the block's streets.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <functional>
#include <string>
#include <vector>

#include "city/lot_subdivision.h"

namespace veduta {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;

inline constexpr double kAreaTolerance = 1e-3;    // m²
inline constexpr double kLengthTolerance = 1e-3;  // m

ExactPolygon exact(const std::vector<Vec2f> &points);
double area(const ExactPolygon &polygon);
double intersectionArea(const ExactPolygon &a, const ExactPolygon &b);
// The area the polygons cover together: their areas' sum when they do not overlap.
double unionArea(const std::vector<ExactPolygon> &polygons);

// Whether the segment from `a` to `b` lies along a street edge of the block.
bool onStreetEdge(Vec2f a, Vec2f b, const Block &block);
bool nearBlockPoint(Vec2f p, const Block &block);
// The length of the lot's flagged edges.
double frontage(const Footprint &lot);

// A lot is a simple counter-clockwise polygon with a street flag per edge, inside the block's
// outline (a fatal gtest failure when it is no polygon at all).
void expectLotInside(const Footprint &lot, const ExactPolygon &outline);

// Every lot is a simple counter-clockwise polygon inside the block, apart from the others, with a
// flagged edge, every flagged edge on a street edge of the block (gtest failures otherwise).
void expectValidLots(const Block &block, const std::vector<Footprint> &lots);

// An algorithm over 300 random blocks (lot_test_blocks.h): valid lots, or a LotError with a
// message; more than 200 of the blocks get lots.
using Subdivision =
    std::function<std::vector<Footprint>(const Block &, const LotSettings &, uint32_t seed, uint32_t blockId)>;
void expectRandomBlocksGiveValidLots(const Subdivision &subdivide);

// Whether the two are the same lots, point for point.
bool sameLots(const std::vector<Footprint> &a, const std::vector<Footprint> &b);

// The message of the std::runtime_error `call` throws; empty when it throws none.
std::string errorOf(const std::function<void()> &call);

}  // namespace veduta
