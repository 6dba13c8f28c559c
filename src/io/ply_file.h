// PLY files (ASCII, binary little- and big-endian) read as a MapMesh: vertex x, y, z in double
// whatever their stored type (float or double), normals nx, ny, nz and texture coordinates
// (u, v; s, t; texture_u, texture_v) when every vertex has them, faces as fans of triangles.
// Other elements and properties are skipped.
#pragma once

#include <filesystem>

#include "io/map_mesh.h"

namespace veduta {

// Throws InputError naming the file, and the line of the header or of an ASCII body where
// the fault is (a binary body's byte offset), when it is no PLY file of triangles.
MapMesh readPlyFile(const std::filesystem::path &file);

}  // namespace veduta
