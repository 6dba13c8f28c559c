// RenderScene: the one contract between generation and rendering. Generators fill it through
// RenderSceneBuilder; the path tracer, the preview and the exporters read it and nothing else.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/camera.h"
#include "scene/environment.h"
#include "scene/fog.h"
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

// What a generator knows of a building it made, in the scene frame: `veduta compare` measures
// buildings by it (docs/compare.md); the renderer ignores it.
struct BuildingRecord {
    uint32_t id = 0;   // the building id (IndexBuilding pass)
    float base = 0;    // where it stands
    float eaves = 0;   // the top of its walls
    float ridge = 0;   // its highest point
    std::string roof;  // the roof type it has (roofTypeName), empty when none veduta knows
    // Its ground plan: outlines in scene x/y (counter-clockwise seen from above) whose union it
    // stands on; empty when the generator does not know it.
    std::vector<std::vector<Vec2f>> footprint;
};

// What the scene's models cost their makers: rule-file lines and the parameters a scene gives
// procedural buildings, against the surfaces and vertices of modelled ones.
struct ModelEffort {
    uint64_t ruleLines = 0;
    uint64_t parameters = 0;
    uint64_t surfaces = 0;
    uint64_t vertices = 0;
};

// What a stored triangle costs until the image is rendered: its share of a world mesh (three
// vertices of its own with texture coordinates, indices, material) and of the BVH at its
// build's peak (`veduta info`'s bvh_peak_bytes per triangle: about 134), rounded up.
inline constexpr uint64_t kBytesPerTriangle = 220;
// What an instance costs the same way: the Instance and its share of the top-level BVH (406
// bytes at the end of the build for a city of 4.55 million, issue 21's table; its peak about
// half again).
inline constexpr uint64_t kBytesPerInstance = 700;

// Levels of detail a generator chose, counted for `veduta info` and the benchmarks.
struct LodCounts {
    uint64_t buildings = 0, triangles = 0, meshes = 0, instances = 0;
    uint64_t merged = 0;  // of the buildings, those in a mesh shared with others (no building id)
    LodCounts &operator+=(const LodCounts &o) {
        buildings += o.buildings;
        triangles += o.triangles;
        meshes += o.meshes;
        instances += o.instances;
        merged += o.merged;
        return *this;
    }
};

// Eq 1's densities of the lots a plan generator built, summed per BauNVO zone (Table 2), with
// the zone's caps: for `veduta info`, which reports and does not judge (docs/slg.md).
struct DensityTotals {
    uint64_t lots = 0;
    double lotArea = 0, footprintArea = 0, floorArea = 0;  // m²
    double grzCap = 0, gfzCap = 0;
    DensityTotals &operator+=(const DensityTotals &o) {
        lots += o.lots;
        lotArea += o.lotArea;
        footprintArea += o.footprintArea;
        floorArea += o.floorArea;
        grzCap = o.grzCap, gfzCap = o.gfzCap;
        return *this;
    }
};

struct RenderScene {
    std::vector<BakedMesh> meshes;
    std::vector<Mesh> prototypes;
    std::vector<Instance> instances;
    std::vector<Material> materials;
    Camera camera;
    Sun sun;
    Environment environment;
    Fog fog;
    RenderSettings settings;
    std::shared_ptr<const Textures> textures;  // null when no material has maps
    std::vector<BuildingRecord> buildings;     // one per building a generator made
    ModelEffort effort;
    std::map<std::string, LodCounts> lods;           // by "generator/level", e.g. "slg/box"
    std::map<std::string, DensityTotals> densities;  // by BauNVO zone

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

    // Generators that can draw things coarser keep what they add under this many bytes
    // (kBytesPerTriangle, kBytesPerInstance) and warn when they coarsen (docs/performance.md).
    void setGeometryBudget(uint64_t bytes) { geometryBudget_ = bytes; }
    uint64_t geometryBytesLeft() const;

    void countLod(const std::string &level, const LodCounts &counts);
    void countDensity(const std::string &zone, const DensityTotals &totals) { scene_.densities[zone] += totals; }
    void recordBuilding(BuildingRecord record) { scene_.buildings.push_back(std::move(record)); }
    void addEffort(const ModelEffort &effort);

    void setCamera(const Camera &camera) { scene_.camera = camera; }
    void setSun(const Sun &sun) { scene_.sun = sun; }
    void setEnvironment(const Environment &environment) { scene_.environment = environment; }
    void setFog(const Fog &fog) { scene_.fog = fog; }
    void setSettings(const RenderSettings &settings) { scene_.settings = settings; }
    void setTextures(std::shared_ptr<const Textures> textures) { scene_.textures = std::move(textures); }

    RenderScene build() &&;

  private:
    RenderScene scene_;
    std::unordered_map<std::string, MaterialId> materialsByName_;
    uint64_t geometryBudget_ = UINT64_MAX;
    uint64_t storedTriangles_ = 0;  // of the meshes and prototypes added so far
    uint64_t instances_ = 0;
};

}  // namespace veduta
