#include "scene/render_scene.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "scene/tangents.h"

namespace veduta {

uint64_t RenderScene::effectiveTriangleCount() const {
    uint64_t count = 0;
    for (const BakedMesh &m : meshes) count += m.mesh.triangleCount();
    for (const Instance &instance : instances) count += prototypes[instance.prototype].triangleCount();
    return count;
}

MaterialId RenderSceneBuilder::addMaterial(Material material) {
    auto id = MaterialId(scene_.materials.size());
    materialsByName_[material.name] = id;
    scene_.materials.push_back(std::move(material));
    return id;
}

MaterialId RenderSceneBuilder::findMaterial(const std::string &name) const {
    auto it = materialsByName_.find(name);
    return it == materialsByName_.end() ? kNoMaterial : it->second;
}

MaterialId RenderSceneBuilder::findOrAddMaterial(Material fallback) {
    MaterialId found = findMaterial(fallback.name);
    return found != kNoMaterial ? found : addMaterial(std::move(fallback));
}

void RenderSceneBuilder::addMesh(const Mesh &mesh, const Transform &objectToWorld, ObjectId objectId,
                                 uint32_t buildingId, uint32_t instanceId) {
    BakedMesh baked;
    baked.mesh.append(mesh, objectToWorld);
    baked.objectId = objectId;
    baked.buildingId = buildingId;
    baked.instanceId = instanceId;
    storedTriangles_ += baked.mesh.triangleCount();
    scene_.meshes.push_back(std::move(baked));
}

void RenderSceneBuilder::addWorldMesh(Mesh mesh, ObjectId objectId, uint32_t buildingId) {
    BakedMesh baked;
    baked.mesh = std::move(mesh);
    baked.objectId = objectId;
    baked.buildingId = buildingId;
    storedTriangles_ += baked.mesh.triangleCount();
    scene_.meshes.push_back(std::move(baked));
}

uint64_t RenderSceneBuilder::geometryBytesLeft() const {
    uint64_t used = storedTriangles_ * kBytesPerTriangle + instances_ * kBytesPerInstance;
    return used >= geometryBudget_ ? 0 : geometryBudget_ - used;
}

void RenderSceneBuilder::countLod(const std::string &level, const LodCounts &counts) { scene_.lods[level] += counts; }

void RenderSceneBuilder::addEffort(const ModelEffort &effort) {
    ModelEffort &sum = scene_.effort;
    sum.ruleLines += effort.ruleLines;
    sum.parameters += effort.parameters;
    sum.surfaces += effort.surfaces;
    sum.vertices += effort.vertices;
}

PrototypeId RenderSceneBuilder::addPrototype(Mesh mesh) {
    storedTriangles_ += mesh.triangleCount();
    scene_.prototypes.push_back(std::move(mesh));
    return PrototypeId(scene_.prototypes.size() - 1);
}

void RenderSceneBuilder::addInstance(const Instance &instance) {
    if (instance.prototype >= scene_.prototypes.size()) throw std::out_of_range("instance of an unknown prototype");
    ++instances_;
    scene_.instances.push_back(instance);
}

RenderScene RenderSceneBuilder::build() && {
    std::vector<uint32_t> uses(scene_.prototypes.size(), 0);
    for (const Instance &instance : scene_.instances) ++uses[instance.prototype];

    // Bake prototypes used once; renumber the others densely and drop unused ones.
    std::vector<PrototypeId> newId(scene_.prototypes.size(), 0);
    std::vector<Mesh> shared;
    for (size_t p = 0; p < scene_.prototypes.size(); ++p) {
        if (uses[p] > 1) {
            newId[p] = PrototypeId(shared.size());
            shared.push_back(std::move(scene_.prototypes[p]));
        }
    }
    // The kept instances move to the front in place: a city's instance list is large, and a
    // second one would double its memory for a moment.
    size_t kept = 0;
    for (size_t i = 0; i < scene_.instances.size(); ++i) {
        Instance instance = scene_.instances[i];
        if (uses[instance.prototype] > 1) {
            instance.prototype = newId[instance.prototype];
            scene_.instances[kept++] = instance;
            continue;
        }
        Mesh mesh = scene_.prototypes[instance.prototype];
        if (instance.materialOverride != kNoMaterial) mesh.setMaterial(instance.materialOverride);
        addMesh(mesh, instance.objectToWorld, instance.objectId, instance.buildingId, instance.instanceId);
    }
    scene_.instances.resize(kept);
    scene_.instances.shrink_to_fit();
    scene_.prototypes = std::move(shared);
    // Normal maps need tangents, and only they: other scenes keep the memory.
    bool normalMapped = std::any_of(scene_.materials.begin(), scene_.materials.end(),
                                    [](const Material &m) { return m.normalMap != kNoTexture; });
    // Each mesh's tangents are its own: on all cores, the same on any number of threads. On one
    // core they were an eighth of building a city of twenty thousand buildings (bench_city_scale).
    if (normalMapped) {
        tbb::parallel_for(size_t(0), scene_.meshes.size(), [&](size_t i) { computeTangents(scene_.meshes[i].mesh); });
        tbb::parallel_for(size_t(0), scene_.prototypes.size(),
                          [&](size_t i) { computeTangents(scene_.prototypes[i]); });
    }
    return std::move(scene_);
}

}  // namespace veduta
