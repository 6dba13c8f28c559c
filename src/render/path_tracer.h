// The unidirectional path tracer: diffuse BSDF sampling, next-event estimation to the sun,
// a constant environment, Russian roulette.
#pragma once

#include <cstdint>

#include "render/bvh.h"
#include "render/sampler.h"
#include "render/surface_interaction.h"

namespace veduta {

struct RayCounts {
    uint64_t camera = 0;
    uint64_t bounce = 0;
    uint64_t shadow = 0;

    uint64_t total() const { return camera + bounce + shadow; }
    RayCounts &operator+=(const RayCounts &o) {
        camera += o.camera;
        bounce += o.bounce;
        shadow += o.shadow;
        return *this;
    }
};

class PathTracer {
  public:
    PathTracer(const RenderScene &scene, const Bvh &bvh);

    // Radiance arriving along the camera ray. Sample dimensions are consumed in a fixed order
    // per bounce (light, BSDF, roulette), so the result is a pure function of the sampler.
    Vec3f radiance(const Ray &cameraRay, PixelSampler &sampler, RayCounts &counts) const;

  private:
    Vec3f sunLight(const SurfaceInteraction &si, const Vec3f &albedo, Vec2f u, RayCounts &counts) const;
    Vec3f escapedRadiance(const Ray &ray, bool cameraRay) const;

    const RenderScene &scene_;
    const Bvh &bvh_;
    SurfaceLookup surfaces_;
    // The sun as next-event estimation samples it, worked out once.
    bool sunIsDisc_;
    float sunOneMinusCosRadius_;
    Frame sunFrame_;
    Vec3f sunDiscRadiance_;
    Vec3f sunIncidentPerSample_;  // radiance over the cone's pdf, or the irradiance of a point sun
};

}  // namespace veduta
