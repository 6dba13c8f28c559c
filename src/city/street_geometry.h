// Street surfaces from a street network (issue 7; Bilke 2009 drew flat single-colour rectangles,
// Bilke 2009, §2): carriageways as ribbons of each street's width joined at the nodes into one
// surface, sidewalks as a band around it raised by a kerb, and the kerb faces between them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vecmath.h"
#include "geo/grid_lines.h"
#include "scene/mesh.h"

namespace veduta {

struct StreetNetwork {
    struct Street {
        uint32_t from = 0, to = 0;  // node indices
        float width = 5;            // carriageway, metres
    };
    std::vector<Vec2f> nodes;
    std::vector<Street> streets;
    float height = 0;  // the ground the streets lie on
};

struct StreetStyle {
    float sidewalkWidth = 2.5f;
    float kerbHeight = 0.12f;
    float lift = 0.01f;  // the carriageway above the ground, so that it does not fight a ground plane
};

// Surfaces the street meshes' triangleMaterials hold.
enum StreetSurface : MaterialId { StreetCarriageway = 0, StreetSidewalk = 1, StreetKerb = 2, StreetJunction = 3 };

// A node's round joint is a polygon of this many sides circumscribing its circle.
inline constexpr int kStreetJointSides = 16;

// A junction (three or more streets at a node) reaches this many of its widest street's half
// widths from the node: √2 takes in the corners of the square where two streets cross.
inline constexpr float kJunctionReach = 1.4142f;

// A tile of the street surfaces is split while more pieces than this reach it (street_regions.h:
// those of the carriageway, of the carriageway with its sidewalks and the junctions' joints
// together; a junction of a grid and its streets bring about six). bench_city_scale's
// BM_StreetTileSize: 256 to 1024 cost the same within 5 % on the 16 km² grid, a quarter less
// than one tile; 512 keeps the example scenes' towns (up to 475 pieces) one tile each.
inline constexpr size_t kStreetPiecesPerTile = 512;

// One mesh: the carriageway at height + lift, its junctions apart (StreetJunction, the same
// height), the sidewalks at height + lift + kerbHeight, the kerbs between; normals up (kerbs: towards the road),
// texture coordinates in metres (x, y). Streets of zero length are skipped. Made tile by tile
// (street_regions.h), a tile split while more than `piecesPerTile` pieces reach it (tests make
// tiles small), on all cores, the same on any number of threads; a network of one tile is one
// union, as it always was.
Mesh streetGeometry(const StreetNetwork &network, const StreetStyle &style = {},
                    size_t piecesPerTile = kStreetPiecesPerTile);

// The street area (carriageways and sidewalks) as overlapping pieces whose union it is: every
// street's strip and every node's joint, each widened by the sidewalks, counter-clockwise, in
// double. For cutting it into a landscape's terrain (CityStreet, generateLandscape).
std::vector<std::vector<Vec2d>> streetAreaPieces(const StreetNetwork &network, const StreetStyle &style = {});

// What is left of a block's outline (counter-clockwise, x/y) once the streets and their
// sidewalks are taken away: the pieces' outlines, counter-clockwise, each with the edges that
// face a street flagged (their outward side lies on a sidewalk). Where Bilke's blocks run
// along the streets' centrelines, buildings stand at the back of the sidewalk.
struct BuildableArea {
    std::vector<Vec2f> outline;
    std::vector<bool> streetEdges;
};
// The streets near the block are asked of `index` (street_index.h: the network's, made once for
// all its blocks) where one is given, else measured one by one; the areas are the same.
class StreetIndex;
std::vector<BuildableArea> buildableAreas(const std::vector<Vec2f> &block, const StreetNetwork &network,
                                          const StreetStyle &style = {}, const StreetIndex *index = nullptr);

}  // namespace veduta
