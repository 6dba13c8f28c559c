// RenderScene: the one contract between generation and rendering. Generators fill it through
// RenderSceneBuilder; the path tracer, the preview and the exporters read it and nothing else.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/camera.h"
#include "scene/environment.h"
#include "scene/material.h"
#include "scene/mesh.h"
#include "scene/render_settings.h"
#include "scene/sun.h"
#include "scene/textures.h"

namespace veduta {

using PrototypeId = uint32_t;
using ObjectId = uint32_t;

// A world-space mesh that appears once.
struct BakedMesh {
    Mesh mesh;
    ObjectId objectId = 0;
    uint32_t buildingId = 0;  // the building it is part of; 0: none
    uint32_t instanceId = 0;  // 1 + the index of the <instance> it was baked from; 0: none
};

// One placement of a prototype mesh.
struct Instance {
    Transform objectToWorld;
    PrototypeId prototype = 0;
    MaterialId materialOverride = kNoMaterial;  // replaces every triangle's material when set
    ObjectId objectId = 0;
    uint32_t buildingId = 0;  // the building it is part of; 0: none
    uint32_t instanceId = 0;  // 1 + the index of its <instance> element; 0: shared geometry
};

struct RenderScene {
    std::vector<BakedMesh> meshes;
    std::vector<Mesh> prototypes;
    std::vector<Instance> instances;
    std::vector<Material> materials;
    Camera camera;
    Sun sun;
    Environment environment;
    RenderSettings settings;
    std::shared_ptr<const Textures> textures;  // null when no material has maps

    uint64_t effectiveTriangleCount() const;  // counting every instance's triangles
};

// Collects what generators emit and decides how it is stored: a prototype placed once is
// baked into world space (an instance would only cost a BVH level), one placed several times
// stays shared.
class RenderSceneBuilder {
  public:
    MaterialId addMaterial(Material material);
    // The id of a material added before, or kNoMaterial.
    MaterialId findMaterial(const std::string &name) const;
    // The scene's material of `fallback`'s name if it has one, else `fallback`, added: how
    // generators give their surfaces materials a scene may restyle.
    MaterialId findOrAddMaterial(Material fallback);
    const std::vector<Material> &materials() const { return scene_.materials; }

    void addMesh(const Mesh &mesh, const Transform &objectToWorld, ObjectId objectId, uint32_t buildingId = 0,
                 uint32_t instanceId = 0);
    // A mesh already in world space, taken over without a copy.
    void addWorldMesh(Mesh mesh, ObjectId objectId, uint32_t buildingId = 0);
    PrototypeId addPrototype(Mesh mesh);
    void addInstance(const Instance &instance);

    void setCamera(const Camera &camera) { scene_.camera = camera; }
    void setSun(const Sun &sun) { scene_.sun = sun; }
    void setEnvironment(const Environment &environment) { scene_.environment = environment; }
    void setSettings(const RenderSettings &settings) { scene_.settings = settings; }
    void setTextures(std::shared_ptr<const Textures> textures) { scene_.textures = std::move(textures); }

    RenderScene build() &&;

  private:
    RenderScene scene_;
    std::unordered_map<std::string, MaterialId> materialsByName_;
};

}  // namespace veduta
