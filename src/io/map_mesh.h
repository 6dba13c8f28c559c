// A triangle mesh as a file in map coordinates holds it: positions in double (x easting or
// longitude, y northing or latitude, z height) until they are placed in a scene's frame
// (io/georeferenced_mesh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vecmath.h"
#include "geodesy/crs.h"

namespace veduta {

struct MapMesh {
    std::vector<CrsCoordinate> positions;
    std::vector<Vec3f> normals;     // per vertex, in the file's grid; empty: none
    std::vector<Vec2f> uvs;         // per vertex; empty: none
    std::vector<uint32_t> indices;  // three per triangle
};

}  // namespace veduta
