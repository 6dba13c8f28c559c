// Roads, paths and rails as ribbons draped on the terrain (Rilling 2006, ch. 6): a strip of the
// line's width, level across and following the terrain along, never below the surface
// (Rilling's thesis let bilinear heights pierce it, its Abb. 66). docs/draping.md.
#pragma once

#include "geo/atkis.h"
#include "geo/terrain_surface.h"
#include "geodesy/local_frame.h"
#include "scene/mesh.h"

namespace veduta {

struct RibbonOptions {
    double lift = 0.05;        // metres the ribbon keeps above the surface at least (ribbonLift)
    double tileLength = 10.0;  // metres of ribbon per texture repeat along it (v)
    double miterLimit = 2.0;   // a corner's offset at most this many half widths
};

// The lift that orders crossing ribbons: rail 0.09 m over road 0.07 m over path and the rest
// 0.05 m, so that where two meet at their least clearance the higher class is seen.
double ribbonLift(LandClass landClass);

// The ribbon of `centre` (the grid's CRS) and `width`, in local coordinates, up-facing, welded
// along its length. The centre line is cut at the surface's cell lines. Each cross-section
// starts at the highest ground across it plus `lift`; each piece between two cuts (level
// across, linear along) is then raised, ends together, until it lies `lift` above the surface
// everywhere (TerrainSurface::maxAbove of its two triangles), one pass from the start. Corners use the averaged
// perpendicular (a miter, clamped at miterLimit), so pieces share their corner vertices: no gaps. u is the distance
// right of the centre line / tileLength (−width / 2 at the left edge), v = distance along the centre / tileLength. An
// empty mesh for fewer than 2 distinct points or a line off the terrain. Throws InputError for a non-finite point or
// width ≤ 0.
Mesh drapeRibbon(const MapLine &centre, double width, const TerrainSurface &surface, const LocalFrame &frame,
                 const RibbonOptions &options);

}  // namespace veduta
