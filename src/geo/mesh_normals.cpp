#include "geo/mesh_normals.h"

#include <cmath>

namespace veduta {

std::vector<Vec3f> areaWeightedNormals(const Mesh &mesh) {
    std::vector<Vec3d> sums(mesh.positions.size());
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3f &p0 = mesh.positions[mesh.indices[3 * t]];
        const Vec3f &p1 = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3f &p2 = mesh.positions[mesh.indices[3 * t + 2]];
        double ax = double(p1.x) - p0.x, ay = double(p1.y) - p0.y, az = double(p1.z) - p0.z;
        double bx = double(p2.x) - p0.x, by = double(p2.y) - p0.y, bz = double(p2.z) - p0.z;
        Vec3d n{ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
        for (size_t k = 0; k < 3; ++k) {
            Vec3d &s = sums[mesh.indices[3 * t + k]];
            s.x += n.x, s.y += n.y, s.z += n.z;
        }
    }
    std::vector<Vec3f> normals;
    normals.reserve(sums.size());
    for (const Vec3d &s : sums) {
        double length = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
        normals.push_back(length > 0 ? Vec3f(float(s.x / length), float(s.y / length), float(s.z / length))
                                     : Vec3f(0, 0, 1));
    }
    return normals;
}

}  // namespace veduta
