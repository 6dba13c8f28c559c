#include "io/export_mesh_parts.h"

#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace veduta {

namespace {

Vec3f faceNormal(const Mesh &mesh, size_t triangle) {
    const uint32_t *idx = &mesh.indices[3 * triangle];
    Vec3f n = cross(mesh.positions[idx[1]] - mesh.positions[idx[0]], mesh.positions[idx[2]] - mesh.positions[idx[0]]);
    float len = length(n);
    return len > 0 ? n / len : Vec3f{0, 0, 1};
}

Vec3f unit(const Vec3f &v) {
    float len = length(v);
    return len > 0 ? v / len : v;
}

std::map<MaterialId, std::vector<uint32_t>> trianglesByMaterial(const Mesh &mesh, size_t materialCount,
                                                                MaterialId materialOverride) {
    std::map<MaterialId, std::vector<uint32_t>> out;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        MaterialId material = materialOverride != kNoMaterial ? materialOverride : mesh.triangleMaterials[t];
        if (material >= materialCount)
            throw std::out_of_range(fmt::format("a triangle's material {} of {}", material, materialCount));
        out[material].push_back(uint32_t(t));
    }
    return out;
}

// Builds parts one after the other, reusing one vertex map over the whole mesh.
class PartBuilder {
  public:
    PartBuilder(const Mesh &mesh, const PartOptions &options) :
        mesh_(mesh),
        options_(options),
        normalTransform_(options.transform.normalTransform()),
        faceted_(mesh.normals.size() != mesh.positions.size()),
        uvs_(mesh.uvs.size() == mesh.positions.size()),
        newIndex_(mesh.vertexCount(), kUnused) {}

    MeshPart build(MaterialId material, const Material &look, const std::vector<uint32_t> &triangles) {
        MeshPart part;
        part.material = material;
        bool tangents = material < options_.tangents.size() && options_.tangents[material] && uvs_ &&
            mesh_.tangents.size() == mesh_.positions.size();
        part.indices.reserve(3 * triangles.size());
        std::vector<uint32_t> touched;
        for (uint32_t t : triangles) {
            for (int k = 0; k < 3; ++k) {
                uint32_t v = mesh_.indices[3 * t + k];
                if (faceted_ || newIndex_[v] == kUnused) {
                    newIndex_[v] = uint32_t(part.positions.size());
                    touched.push_back(v);
                    addVertex(part, v, t, look, tangents);
                }
                part.indices.push_back(newIndex_[v]);
            }
        }
        for (uint32_t v : touched) newIndex_[v] = kUnused;
        return part;
    }

  private:
    static constexpr uint32_t kUnused = ~0u;

    void addVertex(MeshPart &part, uint32_t v, uint32_t triangle, const Material &look, bool tangents) {
        part.positions.push_back(options_.transform.applyPoint(mesh_.positions[v]));
        Vec3f n = faceted_ ? faceNormal(mesh_, triangle) : mesh_.normals[v];
        part.normals.push_back(unit(normalTransform_.applyVector(n)));
        if (uvs_) {
            Vec2f uv{mesh_.uvs[v].x / look.textureSize.x, mesh_.uvs[v].y / look.textureSize.y};
            part.uvs.push_back(options_.flipV ? Vec2f{uv.x, 1 - uv.y} : uv);
        }
        if (tangents) {
            Vec3f t = unit(options_.transform.applyVector(mesh_.tangents[v]));
            float sign = v < mesh_.bitangentSigns.size() && mesh_.bitangentSigns[v] < 0 ? -1.0f : 1.0f;
            part.tangents.push_back({t.x, t.y, t.z, sign});
        }
    }

    const Mesh &mesh_;
    const PartOptions &options_;
    Transform normalTransform_;
    bool faceted_, uvs_;
    std::vector<uint32_t> newIndex_;
};

}  // namespace

std::vector<MeshPart> meshParts(const Mesh &mesh, const std::vector<Material> &materials, const PartOptions &options) {
    PartBuilder builder(mesh, options);
    std::vector<MeshPart> parts;
    for (const auto &[material, triangles] : trianglesByMaterial(mesh, materials.size(), options.materialOverride)) {
        parts.push_back(builder.build(material, materials[material], triangles));
    }
    return parts;
}

const std::vector<MeshPart> &InstanceCopies::local(const Instance &instance) {
    auto key = std::make_pair(instance.prototype, instance.materialOverride);
    auto found = local_.find(key);
    if (found != local_.end()) return found->second;
    PartOptions options;
    options.materialOverride = instance.materialOverride;
    return local_.emplace(key, meshParts(scene_.prototypes.at(instance.prototype), scene_.materials, options))
        .first->second;
}

std::vector<MeshPart> InstanceCopies::placed(const Instance &instance) {
    std::vector<MeshPart> parts = local(instance);
    Transform normals = instance.objectToWorld.normalTransform();
    for (MeshPart &part : parts) {
        for (Vec3f &p : part.positions) p = instance.objectToWorld.applyPoint(p);
        for (Vec3f &n : part.normals) n = unit(normals.applyVector(n));
    }
    return parts;
}

}  // namespace veduta
