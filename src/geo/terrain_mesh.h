// The terrain of a HeightGrid as a triangle mesh in a scene's local frame.
#pragma once

#include "geo/height_grid.h"
#include "geodesy/local_frame.h"
#include "scene/mesh.h"

namespace veduta {

struct TerrainMeshOptions {
    float uvTile = 10;        // metres per texture repeat: uv = local metres / uvTile
    double maxError = 0;      // metres; 0: full resolution, > 0: simplified (below)
    MaterialId material = 0;  // of every triangle
};

// Full resolution (maxError 0): one vertex per node with a height, two triangles per cell
// split along the SW–NE diagonal (the convention of height_queries.h), cells with a NaN
// corner left out. Vertices run row by row from the south, west to east, skipping NaN nodes.
//
// Simplified (maxError > 0): a right-triangulated irregular network (RTIN, as Martini) over
// the grid padded to a square of 2^k + 1 nodes, split until every node lies within maxError
// (vertically) of the triangle over it; crack-free by construction. The error of a triangle
// is bounded as its hypotenuse midpoint's error plus the larger bound of its two children,
// which is a strict bound (Martini's maximum is not). Triangles touching a NaN node or the
// padding are split down to half cells, and half cells with a NaN corner are left out, so
// holes follow the nodes rather than the cells there.
//
// Normals (both modes) are the grid's central differences at each node (one-sided at edges
// and holes): exactly (0, 0, 1) on a level plane. Counter-clockwise seen from above.
Mesh terrainMesh(const HeightGrid &grid, const LocalFrame &frame, const TerrainMeshOptions &options);

}  // namespace veduta
