// Heights between the nodes of a HeightGrid.
//
// The terrain's triangulation convention, shared by terrain_mesh.h and draping: every cell
// with the nodes (c, r), (c+1, r), (c, r+1), (c+1, r+1) is split along its SW–NE diagonal,
// from node (c, r) to node (c+1, r+1), into the south-east triangle (c, r), (c+1, r),
// (c+1, r+1) and the north-west triangle (c, r), (c+1, r+1), (c, r+1). A cell with a NaN
// corner is a hole: no surface, no height.
#pragma once

#include <optional>

#include "geo/height_grid.h"
#include "geodesy/map_point.h"

namespace veduta {

// Bilinear interpolation in the cell around `p`: the node's height at a node, linear along
// the grid lines. nullopt outside the grid or over a hole.
std::optional<double> bilinearHeight(const HeightGrid &grid, const MapPoint &p);

// The height of the triangulated surface (the convention above) at `p`: what a ray sees on
// the full-resolution terrain mesh. nullopt outside the grid or over a hole.
std::optional<double> surfaceHeight(const HeightGrid &grid, const MapPoint &p);

// The slope of the bilinear surface at `p`, in degrees from level (its gradient, smooth within
// a cell). nullopt where bilinearHeight has none.
std::optional<double> slopeDegrees(const HeightGrid &grid, const MapPoint &p);

}  // namespace veduta
