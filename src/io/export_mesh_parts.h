// A mesh as the exporters write it: its triangles split by material, each part with its own
// vertices, already moved into the file's frame.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/render_scene.h"

namespace veduta {

// The triangles of one material. Texture coordinates are divided by the material's texture
// size, so they are what a texture sees (0 … 1 per repeat).
struct MeshPart {
    MaterialId material = 0;
    std::vector<Vec3f> positions, normals;
    std::vector<Vec2f> uvs;                      // empty when the mesh has none
    std::vector<std::array<float, 4>> tangents;  // xyz and the bitangent's sign; empty unless asked
    std::vector<uint32_t> indices;               // three per triangle, into this part's vertices
};

struct PartOptions {
    Transform transform;                        // into the file's frame
    MaterialId materialOverride = kNoMaterial;  // an instance's material for every triangle
    bool flipV = false;                         // v from the image's top (glTF), not its bottom
    std::vector<bool> tangents;                 // by material: whose parts get tangents (a normal map)
};

// The mesh's parts in the order of their material ids. A faceted mesh (no vertex normals) gets
// a vertex per corner with its face's normal, so that other tools do not smooth it across
// shared vertices. Throws std::out_of_range for a material id the scene does not have.
std::vector<MeshPart> meshParts(const Mesh &mesh, const std::vector<Material> &materials, const PartOptions &options);

// The parts of every instance as transformed copies, for formats without instancing (OBJ,
// PLY): each prototype (with its material override) is split once, and each copy only moves
// the split parts.
class InstanceCopies {
  public:
    explicit InstanceCopies(const RenderScene &scene) : scene_(scene) {}

    // The parts of the instance's prototype in the prototype's own frame.
    const std::vector<MeshPart> &local(const Instance &instance);
    // The instance's parts in world space.
    std::vector<MeshPart> placed(const Instance &instance);

  private:
    const RenderScene &scene_;
    std::map<std::pair<PrototypeId, MaterialId>, std::vector<MeshPart>> local_;
};

}  // namespace veduta
