#include "city/prism_building.h"

#include <algorithm>
#include <cmath>

#include "city/footprint.h"

namespace veduta {

int uvRepeats(float length, float tile) { return std::max(1, int(std::lround(length / tile))); }

namespace {

// One cap: the outline's triangles at `height`, facing up or (reversed) down.
void addCap(std::span<const Vec2f> outline, const std::vector<uint32_t> &triangles, float height, bool up,
            MaterialId surface, Mesh &mesh) {
    uint32_t first = uint32_t(mesh.positions.size());
    for (Vec2f p : outline) {
        mesh.positions.push_back(lift(p, height));
        mesh.normals.push_back({0, 0, up ? 1.0f : -1.0f});
        mesh.uvs.push_back(p);
    }
    for (size_t t = 0; t < triangles.size(); t += 3) {
        uint32_t a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
        if (!up) std::swap(b, c);
        mesh.indices.insert(mesh.indices.end(), {first + a, first + b, first + c});
        mesh.triangleMaterials.push_back(surface);
    }
}

void addWall(Vec2f p, Vec2f q, float base, float height, Vec2f tile, Mesh &mesh) {
    Vec2f along = q - p;
    float length = std::hypot(along.x, along.y);
    Vec3f out{along.y / length, -along.x / length, 0};
    float u = float(uvRepeats(length, tile.x)) * tile.x, v = float(uvRepeats(height, tile.y)) * tile.y;
    uint32_t first = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {lift(p, base), lift(q, base), lift(q, base + height), lift(p, base + height)});
    mesh.uvs.insert(mesh.uvs.end(), {{0, 0}, {u, 0}, {u, v}, {0, v}});
    mesh.normals.insert(mesh.normals.end(), 4, out);
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), 2, PrismWall);
}

}  // namespace

Mesh prismBuilding(std::span<const Vec2f> outline, float base, float height, Vec2f tile) {
    Mesh mesh;
    std::vector<uint32_t> triangles = triangulatePolygon(outline);
    for (size_t i = 0; i < outline.size(); ++i)
        addWall(outline[i], outline[(i + 1) % outline.size()], base, height, tile, mesh);
    addCap(outline, triangles, base + height, true, PrismRoof, mesh);
    addCap(outline, triangles, base, false, PrismFloor, mesh);
    return mesh;
}

}  // namespace veduta
