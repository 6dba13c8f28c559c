#include "city/building_pieces.h"

#include <algorithm>
#include <bit>
#include <tuple>

namespace veduta::test {

namespace {

std::vector<uint32_t> bitsOf(const std::vector<float> &values) {
    std::vector<uint32_t> bits;
    for (float v : values) bits.push_back(std::bit_cast<uint32_t>(v));
    return bits;
}

auto key(const Piece &p) { return std::make_tuple(bitsOf(p.positions), std::cref(p.indices), std::cref(p.materials)); }

Piece pieceOf(const Mesh &mesh, const std::vector<Material> &materials) {
    Piece piece;
    for (const Vec3f &p : mesh.positions) piece.positions.insert(piece.positions.end(), {p.x, p.y, p.z});
    piece.indices = mesh.indices;
    for (MaterialId m : mesh.triangleMaterials) piece.materials.push_back(materials[m].name);
    return piece;
}

}  // namespace

bool operator==(const Piece &a, const Piece &b) { return key(a) == key(b); }
bool operator<(const Piece &a, const Piece &b) { return key(a) < key(b); }

std::map<uint32_t, std::vector<Piece>> buildingsOf(const RenderScene &scene) {
    std::map<uint32_t, std::vector<Piece>> buildings;
    for (const BakedMesh &b : scene.meshes) {
        if (b.buildingId != 0) buildings[b.buildingId].push_back(pieceOf(b.mesh, scene.materials));
    }
    for (const Instance &i : scene.instances) {
        if (i.buildingId == 0) continue;
        Mesh prototype = scene.prototypes[i.prototype];
        if (i.materialOverride != kNoMaterial) prototype.setMaterial(i.materialOverride);
        Mesh world;
        world.append(prototype, i.objectToWorld);
        buildings[i.buildingId].push_back(pieceOf(world, scene.materials));
    }
    for (auto &[id, pieces] : buildings) std::sort(pieces.begin(), pieces.end());
    return buildings;
}

}  // namespace veduta::test
