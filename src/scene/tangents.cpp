#include "scene/tangents.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

// The angle at corner p between the edges to a and b; 0 for a degenerate corner.
float cornerAngle(const Vec3f &p, const Vec3f &a, const Vec3f &b) {
    Vec3f e0 = a - p, e1 = b - p;
    float len = length(e0) * length(e1);
    if (len <= 0) return 0;
    return std::acos(std::clamp(dot(e0, e1) / len, -1.0f, 1.0f));
}

}  // namespace

void computeTangents(Mesh &mesh) {
    mesh.tangents.clear();
    mesh.bitangentSigns.clear();
    size_t count = mesh.vertexCount();
    if (count == 0 || mesh.uvs.size() != count || mesh.normals.size() != count) return;

    std::vector<Vec3f> dpdu(count, Vec3f(0.0f)), dpdv(count, Vec3f(0.0f));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const uint32_t *idx = &mesh.indices[3 * t];
        const Vec3f &p0 = mesh.positions[idx[0]];
        Vec3f e1 = mesh.positions[idx[1]] - p0, e2 = mesh.positions[idx[2]] - p0;
        Vec2f uv0 = mesh.uvs[idx[0]], uv1 = mesh.uvs[idx[1]], uv2 = mesh.uvs[idx[2]];
        float du1 = uv1.x - uv0.x, dv1 = uv1.y - uv0.y, du2 = uv2.x - uv0.x, dv2 = uv2.y - uv0.y;
        float det = du1 * dv2 - du2 * dv1;
        // Relative to the uv extent, so that tiny uvs (one texture over a city) still count.
        float scale = std::max({std::abs(du1), std::abs(dv1), std::abs(du2), std::abs(dv2)});
        if (!(std::abs(det) > 1e-9f * scale * scale)) continue;
        Vec3f tu = (e1 * dv2 - e2 * dv1) / det, tv = (e2 * du1 - e1 * du2) / det;
        if (length(tu) <= 0 || length(tv) <= 0) continue;  // all three corners in one place
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = mesh.positions[idx[k]];
            float w = cornerAngle(p, mesh.positions[idx[(k + 1) % 3]], mesh.positions[idx[(k + 2) % 3]]);
            // Unit directions, so that a triangle's weight is its angle and not its uv scale.
            dpdu[idx[k]] += normalize(tu) * w;
            dpdv[idx[k]] += normalize(tv) * w;
        }
    }

    mesh.tangents.resize(count);
    mesh.bitangentSigns.resize(count);
    for (size_t v = 0; v < count; ++v) {
        const Vec3f &n = mesh.normals[v];
        Vec3f t = dpdu[v] - n * dot(n, dpdu[v]);
        float len = length(t);
        mesh.tangents[v] = len > 1e-12f ? t / len : Frame::fromNormal(n).s;
        mesh.bitangentSigns[v] = dot(cross(n, mesh.tangents[v]), dpdv[v]) < 0 ? -1.0f : 1.0f;
    }
}

}  // namespace veduta
