#include "city/terrain_checks.h"

#include <algorithm>

#include "geo/geo_test_terrain.h"

namespace veduta::test {

Vec3d pointIn(const Mesh &m, size_t t, double a, double b) {
    const Vec3f &p = m.positions[m.indices[3 * t]], &q = m.positions[m.indices[3 * t + 1]];
    const Vec3f &r = m.positions[m.indices[3 * t + 2]];
    auto mix = [&](float u, float v, float w) { return (1 - a - b) * double(u) + a * double(v) + b * double(w); };
    return {mix(p.x, q.x, r.x), mix(p.y, q.y, r.y), mix(p.z, q.z, r.z)};
}

size_t pointsBelow(const Mesh &mesh, const TerrainSurface &surface) {
    size_t below = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        for (uint32_t k = 0; k < 33; ++k) {
            double a = k < 3 ? double(k == 1) : unitRandom(uint32_t(t), 2 * k);
            double b = k < 3 ? double(k == 2) : unitRandom(uint32_t(t), 2 * k + 1);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            Vec3d p = pointIn(mesh, t, a, b);
            std::optional<double> ground = surface.heightAt({p.x, p.y});
            if (ground && p.z < *ground) ++below;
        }
    }
    return below;
}

MaterialId materialNamed(const RenderScene &scene, const std::string &name) {
    for (MaterialId m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].name == name) return m;
    return kNoMaterial;
}

std::map<uint32_t, Seat> seats(const RenderScene &scene) {
    std::map<uint32_t, Seat> found;
    MaterialId plinth = materialNamed(scene, "plinth");
    for (const BakedMesh &m : scene.meshes) {
        if (m.buildingId == 0) continue;
        for (size_t t = 0; t < m.mesh.triangleCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                float z = m.mesh.positions[m.mesh.indices[3 * t + size_t(k)]].z;
                Seat &seat = found[m.buildingId];
                float &lowest = m.mesh.triangleMaterials[t] == plinth ? seat.plinth : seat.walls;
                lowest = std::min(lowest, z);
            }
    }
    return found;
}

}  // namespace veduta::test
