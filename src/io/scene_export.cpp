#include "io/scene_export.h"

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Exporter.hpp>

#include "core/atomic_file.h"
#include "core/axes.h"
#include "core/file_extension.h"

namespace veduta {

namespace {

aiMatrix4x4 toAiMatrix(const Transform &t) {
    const auto &m = t.m;
    return {m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], 0, 0, 0, 1};
}

aiColor3D toAiColor(const Vec3f &c) { return {c.x, c.y, c.z}; }

std::string objectName(ObjectId objectId, uint32_t buildingId) {
    if (buildingId == 0) return fmt::format("object_{}", objectId);
    return fmt::format("building_{}/object_{}", buildingId, objectId);
}

// glTF's roughness for a Phong exponent: Walter et al. 2007 match Phong's n to a microfacet
// width α = sqrt(2 / (n + 2)), and glTF's roughness is sqrt(α). Without a specular colour the
// surface is matte whatever n says.
float roughnessFromPhong(const Material &m) {
    if (maxComponent(m.specular) <= 0) return 1;
    return std::pow(2 / (m.shininess + 2), 0.25f);
}

// Reflectance of a dielectric at normal incidence: how much of a glass pane a viewer that knows
// only opacity should show.
float normalReflectance(float ior) {
    float r = (ior - 1) / (ior + 1);
    return r * r;
}

// MTL's Phong model: Kd Ks Ns, and glass as a transmission filter (Tf), an index (Ni) and, for
// viewers that know only dissolve, an opacity (d) equal to what the pane reflects.
void addPhong(aiMaterial &out, const Material &m) {
    aiColor3D diffuse = toAiColor(m.glass ? m.glassTint : m.diffuse);
    aiColor3D specular = toAiColor(m.glass ? Vec3f(1) : m.specular);
    out.AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
    out.AddProperty(&specular, 1, AI_MATKEY_COLOR_SPECULAR);
    out.AddProperty(&m.shininess, 1, AI_MATKEY_SHININESS);
    if (m.glass) {
        aiColor3D tint = toAiColor(m.glassTint);
        float opacity = normalReflectance(m.ior);
        out.AddProperty(&tint, 1, AI_MATKEY_COLOR_TRANSPARENT);
        out.AddProperty(&m.ior, 1, AI_MATKEY_REFRACTI);
        out.AddProperty(&opacity, 1, AI_MATKEY_OPACITY);
    }
}

// glTF's metallic-roughness model, glass through KHR_materials_transmission and _ior. No
// specular colour or shininess: Assimp would then write the archived
// KHR_materials_pbrSpecularGlossiness instead, and no transmission.
void addMetallicRoughness(aiMaterial &out, const Material &m) {
    aiColor3D base = toAiColor(m.glass ? m.glassTint : m.diffuse);
    float metallic = 0;
    float roughness = m.glass ? 0 : roughnessFromPhong(m);
    out.AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
    out.AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
    out.AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
    if (m.glass) {
        float transmission = 1;
        out.AddProperty(&transmission, 1, AI_MATKEY_TRANSMISSION_FACTOR);
        out.AddProperty(&m.ior, 1, AI_MATKEY_REFRACTI);
    }
}

std::unique_ptr<aiMaterial> toAiMaterial(const Material &m, ExportFormat format) {
    auto out = std::make_unique<aiMaterial>();
    aiString name(m.name);
    out->AddProperty(&name, AI_MATKEY_NAME);
    if (format == ExportFormat::Obj) {
        addPhong(*out, m);
    } else {
        addMetallicRoughness(*out, m);
    }
    return out;
}

Vec3f faceNormal(const Mesh &mesh, size_t triangle) {
    const uint32_t *idx = &mesh.indices[3 * triangle];
    Vec3f n = cross(mesh.positions[idx[1]] - mesh.positions[idx[0]], mesh.positions[idx[2]] - mesh.positions[idx[0]]);
    float len = length(n);
    return len > 0 ? n / len : Vec3f{0, 0, 1};
}

// A vertex of an exported mesh: a vertex of the veduta mesh, and for a faceted mesh the
// triangle whose normal it takes.
struct Corner {
    uint32_t vertex;
    uint32_t triangle;
};

// The triangles of `mesh` with material `material`, with their own vertex numbering. A faceted
// mesh (no vertex normals) gets a vertex per corner with its face's normal: Assimp's OBJ writer
// would otherwise make smooth normals across the shared vertices.
std::unique_ptr<aiMesh> meshPart(const Mesh &mesh, const std::vector<uint32_t> &triangles, MaterialId material,
                                 const Material &look, const std::string &name) {
    bool faceted = mesh.normals.size() != mesh.positions.size();
    bool uvs = mesh.uvs.size() == mesh.positions.size();
    constexpr uint32_t kUnused = ~0u;
    std::vector<uint32_t> newIndex(mesh.vertexCount(), kUnused);
    std::vector<Corner> corners;
    std::vector<unsigned> indices;
    for (uint32_t t : triangles) {
        for (int k = 0; k < 3; ++k) {
            uint32_t v = mesh.indices[3 * t + k];
            if (faceted || newIndex[v] == kUnused) {
                newIndex[v] = uint32_t(corners.size());
                corners.push_back({v, t});
            }
            indices.push_back(newIndex[v]);
        }
    }
    auto out = std::make_unique<aiMesh>();
    out->mName = name;
    out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    out->mMaterialIndex = material;
    out->mNumVertices = unsigned(corners.size());
    out->mVertices = new aiVector3D[corners.size()];
    out->mNormals = new aiVector3D[corners.size()];
    if (uvs) {
        out->mTextureCoords[0] = new aiVector3D[corners.size()];
        out->mNumUVComponents[0] = 2;
    }
    for (size_t i = 0; i < corners.size(); ++i) {
        const Vec3f &p = mesh.positions[corners[i].vertex];
        Vec3f n = faceted ? faceNormal(mesh, corners[i].triangle) : mesh.normals[corners[i].vertex];
        out->mVertices[i] = {p.x, p.y, p.z};
        out->mNormals[i] = {n.x, n.y, n.z};
        // The renderer divides by the texture size; the file gets the coordinates textures see.
        if (uvs) {
            const Vec2f &uv = mesh.uvs[corners[i].vertex];
            out->mTextureCoords[0][i] = {uv.x / look.textureSize.x, uv.y / look.textureSize.y, 0};
        }
    }
    out->mNumFaces = unsigned(triangles.size());
    out->mFaces = new aiFace[triangles.size()];
    for (size_t f = 0; f < triangles.size(); ++f) {
        aiFace &face = out->mFaces[f];
        face.mNumIndices = 3;
        face.mIndices = new unsigned[3];
        std::copy_n(&indices[3 * f], 3, face.mIndices);
    }
    return out;
}

// An aiScene under construction: Assimp meshes carry one material each, so a veduta mesh
// becomes one Assimp mesh per material it uses, all hung on the same node.
class AssimpScene {
  public:
    AssimpScene(const RenderScene &scene, ExportFormat format) : scene_(scene) {
        if (scene.materials.empty()) throw std::invalid_argument("a scene to export needs at least one material");
        for (const Material &m : scene.materials) materials_.push_back(toAiMaterial(m, format));
    }

    // Adds `mesh` as it is; returns the indices of its Assimp meshes.
    std::vector<unsigned> addMesh(const Mesh &mesh, const std::string &name) {
        std::map<MaterialId, std::vector<uint32_t>> byMaterial;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) byMaterial[mesh.triangleMaterials[t]].push_back(uint32_t(t));
        std::vector<unsigned> added;
        for (const auto &[material, triangles] : byMaterial) {
            if (material >= scene_.materials.size()) {
                throw std::out_of_range(fmt::format("{}: material {} of {}", name, material, scene_.materials.size()));
            }
            added.push_back(unsigned(meshes_.size()));
            meshes_.push_back(meshPart(mesh, triangles, material, scene_.materials[material], name));
        }
        return added;
    }

    void addNode(const std::string &name, const Transform &transform, const std::vector<unsigned> &meshes) {
        auto node = std::make_unique<aiNode>(name);
        node->mTransformation = toAiMatrix(transform);
        node->mNumMeshes = unsigned(meshes.size());
        node->mMeshes = new unsigned[meshes.size()];
        std::copy(meshes.begin(), meshes.end(), node->mMeshes);
        nodes_.push_back(std::move(node));
    }

    // Hands everything to an aiScene, which frees it in its destructor.
    std::unique_ptr<aiScene> build() && {
        auto out = std::make_unique<aiScene>();
        out->mRootNode = new aiNode("veduta_scene");
        std::vector<aiNode *> children;
        for (auto &node : nodes_) children.push_back(node.release());
        if (!children.empty()) out->mRootNode->addChildren(unsigned(children.size()), children.data());
        out->mNumMaterials = unsigned(materials_.size());
        out->mMaterials = new aiMaterial *[materials_.size()];
        for (size_t i = 0; i < materials_.size(); ++i) out->mMaterials[i] = materials_[i].release();
        out->mNumMeshes = unsigned(meshes_.size());
        out->mMeshes = new aiMesh *[meshes_.size()];
        for (size_t i = 0; i < meshes_.size(); ++i) out->mMeshes[i] = meshes_[i].release();
        return out;
    }

  private:
    const RenderScene &scene_;
    std::vector<std::unique_ptr<aiMaterial>> materials_;
    std::vector<std::unique_ptr<aiMesh>> meshes_;
    std::vector<std::unique_ptr<aiNode>> nodes_;
};

// `mesh` moved by `transform`, every triangle given `materialOverride` when it is set.
Mesh placed(const Mesh &mesh, const Transform &transform, MaterialId materialOverride) {
    Mesh out;
    out.append(mesh, transform);
    if (materialOverride != kNoMaterial) out.setMaterial(materialOverride);
    return out;
}

// glTF: converted to Y up; prototypes stay shared, one mesh per prototype and material override.
std::unique_ptr<aiScene> gltfScene(const RenderScene &scene, ExportFormat format, ExportStats &stats) {
    AssimpScene out(scene, format);
    for (const BakedMesh &baked : scene.meshes) {
        std::string name = objectName(baked.objectId, baked.buildingId);
        out.addNode(name, Transform{}, out.addMesh(placed(baked.mesh, kZUpToYUp, kNoMaterial), name));
    }
    std::map<std::pair<PrototypeId, MaterialId>, std::vector<unsigned>> prototypeMeshes;
    for (const Instance &instance : scene.instances) {
        auto key = std::make_pair(instance.prototype, instance.materialOverride);
        auto found = prototypeMeshes.find(key);
        if (found == prototypeMeshes.end()) {
            std::string name = instance.materialOverride == kNoMaterial
                ? fmt::format("prototype_{}", instance.prototype)
                : fmt::format("prototype_{}/{}", instance.prototype,
                              scene.materials.at(instance.materialOverride).name);
            Mesh mesh = placed(scene.prototypes.at(instance.prototype), kZUpToYUp, instance.materialOverride);
            found = prototypeMeshes.emplace(key, out.addMesh(mesh, name)).first;
        }
        // The prototype's vertices are already Y up: turn them back, place, turn again.
        out.addNode(objectName(instance.objectId, instance.buildingId), kZUpToYUp * instance.objectToWorld * kYUpToZUp,
                    found->second);
    }
    stats.meshes = scene.meshes.size() + prototypeMeshes.size();
    return std::move(out).build();
}

// OBJ: Z up as veduta has it; every instance written out as a transformed copy.
std::unique_ptr<aiScene> objScene(const RenderScene &scene, ExportStats &stats) {
    AssimpScene out(scene, ExportFormat::Obj);
    for (const BakedMesh &baked : scene.meshes) {
        std::string name = objectName(baked.objectId, baked.buildingId);
        out.addNode(name, Transform{}, out.addMesh(baked.mesh, name));
    }
    for (const Instance &instance : scene.instances) {
        std::string name = objectName(instance.objectId, instance.buildingId);
        Mesh copy = placed(scene.prototypes.at(instance.prototype), instance.objectToWorld, instance.materialOverride);
        out.addNode(name, Transform{}, out.addMesh(copy, name));
    }
    stats.meshes = scene.meshes.size() + scene.instances.size();
    return std::move(out).build();
}

const char *assimpFormatId(ExportFormat format) {
    switch (format) {
    case ExportFormat::Obj: return "obj";
    case ExportFormat::Gltf: return "gltf2";
    case ExportFormat::Glb: return "glb2";
    }
    throw std::invalid_argument("unknown export format");
}

// Writes the blob and those after it, each to a temporary, and renames them only when all are
// written: the side files (.mtl, .bin) first, the main file (the first blob) last. `published`
// collects the files renamed into place.
void writeBlobs(const aiExportDataBlob *blob, const std::filesystem::path &folder,
                std::vector<std::filesystem::path> &published) {
    if (!blob) return;
    std::filesystem::path file = folder / blob->name.C_Str();
    writeFileAtomically(file, [&](const std::filesystem::path &temporary) {
        writeWholeFile(temporary, blob->data, blob->size, file);
        writeBlobs(blob->next, folder, published);
    });
    published.push_back(file);
}

// If the main file cannot be renamed into place, the side files already are: they are removed,
// since nothing refers to them.
size_t writeAllOrNothing(const aiExportDataBlob &blob, const std::filesystem::path &folder) {
    std::vector<std::filesystem::path> published;
    try {
        writeBlobs(&blob, folder, published);
    } catch (...) {
        std::error_code ignored;
        for (const std::filesystem::path &file : published) std::filesystem::remove(file, ignored);
        throw;
    }
    return published.size();
}

}  // namespace

std::optional<ExportFormat> exportFormatForPath(const std::filesystem::path &path) {
    std::string extension = lowercaseExtension(path);
    if (extension == ".obj") return ExportFormat::Obj;
    if (extension == ".gltf") return ExportFormat::Gltf;
    if (extension == ".glb") return ExportFormat::Glb;
    return std::nullopt;
}

ExportStats exportScene(const RenderScene &scene, const std::filesystem::path &out, ExportFormat format) {
    ExportStats stats;
    stats.instances = scene.instances.size();
    stats.triangles = scene.effectiveTriangleCount();
    std::unique_ptr<aiScene> assimpScene =
        format == ExportFormat::Obj ? objScene(scene, stats) : gltfScene(scene, format, stats);

    Assimp::Exporter exporter;
    Assimp::ExportProperties properties;
    // Side files are named after this (city.obj → city.mtl, city.gltf → city.bin), and the main
    // file refers to them by it.
    properties.SetPropertyString(AI_CONFIG_EXPORT_BLOB_NAME, out.filename().string());
    const aiExportDataBlob *blob = exporter.ExportToBlob(assimpScene.get(), assimpFormatId(format), 0, &properties);
    if (!blob) throw std::runtime_error(fmt::format("{}: cannot export: {}", out.string(), exporter.GetErrorString()));
    stats.files = writeAllOrNothing(*blob, out.parent_path());
    return stats;
}

}  // namespace veduta
