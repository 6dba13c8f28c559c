// The street surfaces as exact regions, worked out tile by tile (issue 21). One union of a whole
// network's pieces grew faster than the town (n^2.3 on grids of blocks); each tile instead
// joins only the pieces that reach it (box_tiles.h) and keeps the part of the union inside it.
// The tiles do not overlap and cover the streets, so that their regions together are the
// whole network's union, piece for piece the same point set; a network of few pieces is one
// tile, and its regions are that union exactly as before. Exact constructions (CGAL's Epeck):
// the unions and differences of many overlapping ribbons must not fail.
#pragma once

#include <cstddef>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "city/box_tiles.h"
#include "city/street_geometry.h"
#include "city/street_pieces.h"

namespace veduta {

using StreetKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using StreetPoint = StreetKernel::Point_2;
using StreetSegment = StreetKernel::Segment_2;
using StreetPolygon = CGAL::Polygon_2<StreetKernel>;
using StreetPolygonWithHoles = CGAL::Polygon_with_holes_2<StreetKernel>;
using StreetPolygonSet = CGAL::Polygon_set_2<StreetKernel>;

StreetPolygon toPolygon(const StreetRing &ring);

// The union of every street's ribbon and joint (streetPieces), each widened by `extra` on either
// side. All at once: CGAL joins a range by divide and conquer, where joining piece by piece would
// sweep the growing union once per piece.
StreetPolygonSet streetArea(const StreetNetwork &network, float extra);

// What the tiles are cut from: the pieces, and the tiles with the pieces that reach each, as
// indices into `pieces`: the carriageway's first, then the sidewalks', then the junctions'.
struct StreetTiling {
    std::vector<StreetRing> pieces;
    size_t sidewalkStart = 0, junctionStart = 0;
    std::vector<BoxTile> tiles;
};
StreetTiling streetTiling(const StreetNetwork &network, const StreetStyle &style,
                          size_t piecesPerTile = kStreetPiecesPerTile);

// One tile's street surfaces: the parts of the carriageway outside and inside the junctions,
// the sidewalks (the area of the pieces widened by the sidewalks, less the carriageway), each
// within the tile, and the kerbs: the carriageway's boundary within the tile, the road on the
// left of each segment. Each boundary segment belongs to one tile (the one whose half-open box
// [low, high) holds its middle), so that the tiles' kerbs are the boundary once. A tiling of one
// tile leaves its regions uncut, and its kerbs are every edge of the carriageway's outer
// boundaries and holes, part by part, as CGAL gives them.
struct StreetTileRegions {
    StreetPolygonSet carriageway, between, junctions, sidewalks;
    std::vector<StreetSegment> kerbs;
};
StreetTileRegions streetTileRegions(const StreetTiling &tiling, size_t tile);

}  // namespace veduta
