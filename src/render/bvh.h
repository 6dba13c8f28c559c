// The ray-tracing acceleration structure: Embree 3 with one BVH per prototype and a top-level
// BVH over the baked meshes and the instances. This is the only file pair that sees Embree.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

#include "scene/camera.h"
#include "scene/render_scene.h"

namespace veduta {

struct Hit {
    float t = 0;
    bool instanced = false;
    uint32_t index = 0;      // into RenderScene::instances if instanced, else RenderScene::meshes
    uint32_t primitive = 0;  // triangle within the mesh or prototype
    float u = 0, v = 0;      // barycentrics of vertices 1 and 2
};

// What a shadow ray crossed that lets light through (thin glass, cut-outs): the hits in the
// order of their distance. Holds up to kCapacity; beyond that `overflow` is set and the hits
// are not all there.
struct PassedSurfaces {
    static constexpr uint32_t kCapacity = 32;
    std::array<Hit, kCapacity> hits;
    uint32_t count = 0;
    bool overflow = false;
};

struct BvhStats {
    double buildSeconds = 0;
    int64_t bytes = 0;  // memory Embree holds for the scene after the build
    int64_t peakBytes = 0;
};

class Bvh {
  public:
    // Embree reads the scene's vertex and index arrays in place: `scene` must outlive the Bvh
    // and stay unchanged while it lives.
    explicit Bvh(const RenderScene &scene);
    ~Bvh();
    Bvh(const Bvh &) = delete;
    Bvh &operator=(const Bvh &) = delete;

    // `coherent` tells Embree that neighbouring calls trace similar rays (camera rays).
    std::optional<Hit> intersect(const Ray &ray, bool coherent) const;
    bool occluded(const Ray &ray, float tMax) const;
    // Whether something that stops light lies along the ray before tMax. The surfaces of
    // materials that may let light pass (scene/material.h: passesLight) do not count; those
    // crossed are listed in `passed`, for the caller to weigh, unless the ray is stopped. When
    // `passed.overflow` is set, it crossed more than PassedSurfaces holds and the answer is
    // unknown: trace the ray surface by surface.
    bool occluded(const Ray &ray, float tMax, PassedSurfaces &passed) const;

    const BvhStats &stats() const { return stats_; }
    // The top-level RTCScene, for benchmarks that measure Embree itself on our BVH.
    void *embreeScene() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    BvhStats stats_;
};

}  // namespace veduta
