#include "scene/mesh.h"

#include <algorithm>

namespace veduta {

namespace {

// The same surface with one vertex per triangle corner and face normals, so that a faceted
// mesh can join a smooth one without losing its edges.
Mesh withFaceNormals(const Mesh &m) {
    Mesh out;
    bool hasUvs = m.uvs.size() == m.positions.size();
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const uint32_t *idx = &m.indices[3 * t];
        Vec3f n = cross(m.positions[idx[1]] - m.positions[idx[0]], m.positions[idx[2]] - m.positions[idx[0]]);
        float len = length(n);
        n = len > 0 ? n / len : Vec3f{0, 0, 1};
        for (int k = 0; k < 3; ++k) {
            out.indices.push_back(uint32_t(out.positions.size()));
            out.positions.push_back(m.positions[idx[k]]);
            out.normals.push_back(n);
            if (hasUvs) out.uvs.push_back(m.uvs[idx[k]]);
        }
    }
    out.triangleMaterials = m.triangleMaterials;
    return out;
}

bool hasNormals(const Mesh &m) { return !m.positions.empty() && m.normals.size() == m.positions.size(); }

}  // namespace

void Mesh::append(const Mesh &other, const Transform &transform) {
    if (other.triangleCount() == 0) return;
    // Tangents are computed on the finished mesh (computeTangents); a partial set would be wrong.
    tangents.clear();
    bitangentSigns.clear();
    if (positions.empty()) {
        normals.clear();
        uvs.clear();
    }
    bool empty = positions.empty();
    // Smooth and faceted parts can share a mesh only if both carry vertex normals.
    if (!empty && hasNormals(*this) != hasNormals(other)) {
        if (!hasNormals(other)) {
            append(withFaceNormals(other), transform);
            return;
        }
        *this = withFaceNormals(*this);
    }
    bool otherUvs = other.uvs.size() == other.positions.size() && !other.positions.empty();
    bool ourUvs = !empty && uvs.size() == positions.size();
    if (otherUvs && !ourUvs) uvs.assign(positions.size(), Vec2f{});

    auto base = uint32_t(positions.size());
    // A mirroring transform turns triangles inside out; swap two indices to keep them facing out.
    bool flip = transform.determinant() < 0;
    Transform normalTransform = transform.normalTransform();
    for (const Vec3f &p : other.positions) positions.push_back(transform.applyPoint(p));
    if (hasNormals(other)) {
        for (const Vec3f &n : other.normals) normals.push_back(normalize(normalTransform.applyVector(n)));
    }
    if (otherUvs) {
        uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
    } else if (ourUvs) {
        uvs.resize(positions.size(), Vec2f{});
    }
    for (size_t t = 0; t < other.triangleCount(); ++t) {
        uint32_t a = other.indices[3 * t], b = other.indices[3 * t + 1], c = other.indices[3 * t + 2];
        if (flip) std::swap(b, c);
        indices.insert(indices.end(), {base + a, base + b, base + c});
    }
    triangleMaterials.insert(triangleMaterials.end(), other.triangleMaterials.begin(), other.triangleMaterials.end());
    triangleMaterials.resize(triangleCount(), 0);
}

void Mesh::setMaterial(MaterialId material) { triangleMaterials.assign(triangleCount(), material); }

}  // namespace veduta
