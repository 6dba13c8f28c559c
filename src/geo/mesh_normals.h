// Vertex normals of draped meshes (Rilling 2006, §3.1: the area-weighted sum of the adjacent face
// normals), shared by the terrain and the ribbons.
#pragma once

#include <vector>

#include "scene/mesh.h"

namespace veduta {

// Per vertex, the normalised sum of the unnormalised normals (twice the area) of the
// triangles using it, summed in double. On a flat horizontal plane every face normal is
// (0, 0, k), so the result is (0, 0, 1) exactly. A vertex of no triangle gets (0, 0, 1).
std::vector<Vec3f> areaWeightedNormals(const Mesh &mesh);

}  // namespace veduta
