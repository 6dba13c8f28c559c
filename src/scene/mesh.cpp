#include "scene/mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

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

namespace {

// A vertex on a grid fine enough that only vertices meant to be one fall together.
struct WeldKey {
    std::array<int64_t, 3> position{};
    std::array<int32_t, 3> normal{};
    std::array<int32_t, 2> uv{};
    auto operator<=>(const WeldKey &) const = default;
};

// The key's fields mixed into 64 bits (splitmix64's finaliser after each).
uint64_t hashOf(const WeldKey &key) {
    uint64_t h = 0;
    auto add = [&h](uint64_t x) {
        h ^= x + 0x9e3779b97f4a7c15ull;
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
        h ^= h >> 31;
    };
    for (int64_t p : key.position) add(uint64_t(p));
    for (int32_t n : key.normal) add(uint32_t(n));
    for (int32_t u : key.uv) add(uint32_t(u));
    return h;
}

int64_t onGrid(float x, float step) { return int64_t(std::floor(double(x) / step + 0.5)); }

WeldKey weldKey(const Mesh &m, size_t v, bool withNormals, bool withUvs) {
    WeldKey key;
    for (int k = 0; k < 3; ++k) key.position[k] = onGrid(m.positions[v][k], 1e-4f);
    if (withNormals)
        for (int k = 0; k < 3; ++k) key.normal[k] = int32_t(onGrid(m.normals[v][k], 1e-3f));
    if (withUvs) key.uv = {int32_t(onGrid(m.uvs[v].x, 1e-4f)), int32_t(onGrid(m.uvs[v].y, 1e-4f))};
    return key;
}

}  // namespace

Mesh weldVertices(const Mesh &mesh) {
    size_t count = mesh.positions.size();
    bool withNormals = hasNormals(mesh), withUvs = mesh.uvs.size() == count && count > 0;
    // An open-addressing table from key to welded vertex, at most half full: each vertex finds
    // the first one of its key in a probe or two, where sorting the keys took most of the time
    // of baking a building.
    size_t capacity = std::bit_ceil(2 * count + 2), mask = capacity - 1;
    constexpr uint32_t kEmpty = UINT32_MAX;
    std::vector<uint32_t> slots(capacity, kEmpty), remap(count), kept;
    std::vector<WeldKey> keptKeys;
    for (size_t v = 0; v < count; ++v) {
        WeldKey key = weldKey(mesh, v, withNormals, withUvs);
        size_t slot = hashOf(key) & mask;
        while (slots[slot] != kEmpty && keptKeys[slots[slot]] != key) slot = (slot + 1) & mask;
        if (slots[slot] == kEmpty) {
            // The first vertex of its key is kept, in the order the vertices come.
            slots[slot] = uint32_t(kept.size());
            kept.push_back(uint32_t(v));
            keptKeys.push_back(key);
        }
        remap[v] = slots[slot];
    }
    // Copied out without spare room: a city's buildings keep their meshes.
    Mesh welded;
    welded.positions.reserve(kept.size());
    if (withNormals) welded.normals.reserve(kept.size());
    if (withUvs) welded.uvs.reserve(kept.size());
    for (uint32_t v : kept) {
        welded.positions.push_back(mesh.positions[v]);
        if (withNormals) welded.normals.push_back(mesh.normals[v]);
        if (withUvs) welded.uvs.push_back(mesh.uvs[v]);
    }
    welded.indices.reserve(mesh.indices.size());
    for (uint32_t i : mesh.indices) welded.indices.push_back(remap[i]);
    welded.triangleMaterials = mesh.triangleMaterials;
    return welded;
}

}  // namespace veduta
