#include "city/street_regions.h"

#include <algorithm>
#include <iterator>
#include <optional>
#include <utility>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/intersections.h>

namespace veduta {

StreetPolygon toPolygon(const StreetRing &ring) {
    StreetPolygon p;
    for (Vec2f v : ring) p.push_back(StreetPoint(v.x, v.y));
    return p;
}

StreetPolygonSet streetArea(const StreetNetwork &network, float extra) {
    std::vector<StreetPolygon> pieces;
    for (const StreetRing &ring : streetPieces(network, extra)) pieces.push_back(toPolygon(ring));
    StreetPolygonSet area;
    area.join(pieces.begin(), pieces.end());
    return area;
}

namespace {

// What of `a` lies outside `b`, where `b` lies inside `a`: their symmetric difference. CGAL 5.5's
// difference leaves, on some street networks, an arrangement with a face of two outer
// boundaries (its own assertion catches it in a checked build:
// fuzz/regressions/osm/difference_face_of_two_outer_boundaries.osm), where the symmetric
// difference of the same sets does not.
void cutOut(StreetPolygonSet &a, const StreetPolygonSet &b) { a.symmetric_difference(b); }

// A ring's box, exact: its corners are floats.
Box2d boxOf(const StreetRing &ring) {
    Box2d box{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
    for (Vec2f p : ring) box = around(box, {p.x, p.y, p.x, p.y});
    return box;
}

StreetPolygon boxPolygon(const Box2d &box) {
    StreetPolygon p;
    p.push_back(StreetPoint(box.lowX, box.lowY));
    p.push_back(StreetPoint(box.highX, box.lowY));
    p.push_back(StreetPoint(box.highX, box.highY));
    p.push_back(StreetPoint(box.lowX, box.highY));
    return p;
}

// Every edge of the outer boundaries and holes, part by part: the region lies left of each
// (outer boundaries counter-clockwise, holes clockwise).
template <typename Visit>
void forEachBoundaryEdge(const StreetPolygonSet &region, Visit visit) {
    std::vector<StreetPolygonWithHoles> parts;
    region.polygons_with_holes(std::back_inserter(parts));
    auto ring = [&](const StreetPolygon &polygon) {
        for (auto e = polygon.edges_begin(); e != polygon.edges_end(); ++e) visit(*e);
    };
    for (const StreetPolygonWithHoles &part : parts) {
        ring(part.outer_boundary());
        for (const StreetPolygon &hole : part.holes()) ring(hole);
    }
}

bool inside(const StreetPoint &p, const Box2d &box) {
    return box.lowX <= p.x() && p.x() <= box.highX && box.lowY <= p.y() && p.y() <= box.highY;
}

// What of `edge` lies in the closed `box`, in its direction; nothing where that is no segment.
std::optional<StreetSegment> clipped(const StreetSegment &edge, const Box2d &box) {
    if (inside(edge.source(), box) && inside(edge.target(), box)) return edge;
    CGAL::Bbox_2 b = edge.bbox();
    if (!meet(box, {b.xmin(), b.ymin(), b.xmax(), b.ymax()})) return std::nullopt;
    StreetKernel::Iso_rectangle_2 rectangle(StreetPoint(box.lowX, box.lowY), StreetPoint(box.highX, box.highY));
    auto hit = CGAL::intersection(edge, rectangle);
    if (!hit) return std::nullopt;
    const StreetSegment *piece = boost::get<StreetSegment>(&*hit);
    if (!piece) return std::nullopt;
    if (piece->to_vector() * edge.to_vector() < 0) return piece->opposite();
    return *piece;
}

// The boundary of `area` within the tile `box`, each piece kept by the one tile whose half-open
// box holds its middle. `area` is the union of every piece that reaches the closed box, so that
// within it the boundary is the whole network's.
std::vector<StreetSegment> ownedBoundary(const StreetPolygonSet &area, const Box2d &box) {
    std::vector<StreetSegment> owned;
    forEachBoundaryEdge(area, [&](const StreetSegment &edge) {
        std::optional<StreetSegment> piece = clipped(edge, box);
        if (!piece) return;
        StreetPoint middle = CGAL::midpoint(piece->source(), piece->target());
        if (box.lowX <= middle.x() && middle.x() < box.highX && box.lowY <= middle.y() && middle.y() < box.highY)
            owned.push_back(*piece);
    });
    return owned;
}

}  // namespace

StreetTiling streetTiling(const StreetNetwork &network, const StreetStyle &style, size_t piecesPerTile) {
    StreetTiling tiling;
    tiling.pieces = streetPieces(network, 0);
    tiling.sidewalkStart = tiling.pieces.size();
    for (StreetRing &ring : streetPieces(network, style.sidewalkWidth)) tiling.pieces.push_back(std::move(ring));
    tiling.junctionStart = tiling.pieces.size();
    for (StreetRing &ring : junctionJoints(network)) tiling.pieces.push_back(std::move(ring));
    if (tiling.pieces.empty()) return tiling;
    std::vector<Box2d> boxes;
    for (const StreetRing &ring : tiling.pieces) boxes.push_back(boxOf(ring));
    Box2d extent = boxes[0];
    for (const Box2d &box : boxes) extent = around(extent, box);
    // A metre clear of every piece: no boundary lies on the outer tiles' far edges, which own
    // nothing (ownedBoundary).
    extent = {extent.lowX - 1, extent.lowY - 1, extent.highX + 1, extent.highY + 1};
    tiling.tiles = splitIntoTiles(extent, boxes, piecesPerTile);
    return tiling;
}

StreetTileRegions streetTileRegions(const StreetTiling &tiling, size_t t) {
    const BoxTile &tile = tiling.tiles[t];
    std::vector<StreetPolygon> road, wide, joints;
    for (uint32_t i : tile.boxes) {
        std::vector<StreetPolygon> &to = i < tiling.sidewalkStart ? road : i < tiling.junctionStart ? wide : joints;
        to.push_back(toPolygon(tiling.pieces[i]));
    }
    StreetTileRegions r;
    r.carriageway.join(road.begin(), road.end());
    r.sidewalks.join(wide.begin(), wide.end());
    if (tiling.tiles.size() == 1) {
        forEachBoundaryEdge(r.carriageway, [&](const StreetSegment &edge) { r.kerbs.push_back(edge); });
    } else {
        r.kerbs = ownedBoundary(r.carriageway, tile.box);
        StreetPolygon box = boxPolygon(tile.box);
        r.carriageway.intersection(box);
        r.sidewalks.intersection(box);
    }
    cutOut(r.sidewalks, r.carriageway);
    r.junctions.join(joints.begin(), joints.end());
    r.junctions.intersection(r.carriageway);
    r.between = r.carriageway;
    cutOut(r.between, r.junctions);
    return r;
}

}  // namespace veduta
