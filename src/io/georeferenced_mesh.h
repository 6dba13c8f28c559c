// Reading a mesh file whose x and y are eastings and northings of a CRS (z the height), as a
// <mesh crs="EPSG:…"> names it: the coordinates are read in double and go through the scene's
// MapProjection before they become float, so a box at UTM magnitudes keeps its millimetres
// (float32 resolves only 0.5 m at a northing of 5.4 million). Assimp (io/mesh_import.h) reads
// float and cannot; OBJ is read with tinyobjloader in double, PLY with io/ply_file.h.
#pragma once

#include <filesystem>

#include "geodesy/map_projection.h"
#include "scene/mesh.h"

namespace veduta {

// The file's triangles in the scene's render frame. Normals are carried into the scene's
// grid (turned by the angle between the two grids' norths where the CRSs differ). Throws
// InputError naming the file (and the line where the reader knows it) when it cannot be
// read, holds no triangles, has a vertex that is no point of the CRS or is neither OBJ nor PLY.
Mesh importGeoreferencedMesh(const std::filesystem::path &file, const MapProjection &projection);

}  // namespace veduta
