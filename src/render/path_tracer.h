// The unidirectional path tracer: at each surface, next-event estimation to the sun and the
// environment and a BSDF sample to go on, the two combined by multiple importance sampling
// (power heuristic); thin glass and cut-outs let rays and shadow rays pass; Russian roulette.
#pragma once

#include <cstdint>
#include <optional>

#include "film/film.h"
#include "film/render_stats.h"
#include "render/bvh.h"
#include "render/lights.h"
#include "render/material_lookup.h"
#include "render/sampler.h"
#include "render/surface_interaction.h"

namespace veduta {

class PathTracer {
  public:
    PathTracer(const RenderScene &scene, const Bvh &bvh);

    // Radiance arriving along the camera ray. Every bounce takes the same sample pairs (sun
    // and environment if the scene samples them, lobe and roulette, direction) whatever
    // happens and works out those it uses, so the result is a pure function of the sampler.
    // `first`, if given, receives what the camera ray met first, for the film's passes.
    Vec3f radiance(const Ray &cameraRay, PixelSampler &sampler, RayCounts &counts, FirstHit *first = nullptr) const;

    // Only what the camera ray meets first, as radiance() reports it.
    FirstHit firstHit(const Ray &cameraRay, RayCounts &counts) const;

  private:
    // The first surface along the ray that is there: cut-outs are passed through.
    std::optional<SurfaceInteraction> findSurface(Ray ray, bool fromCamera, float footprintSpread,
                                                  RayCounts &counts) const;
    // The sampler's pairs of one path vertex.
    struct VertexPairs {
        uint32_t sun = 0, environment = 0;  // only for lights the scene samples
        uint32_t lobeRoulette = 0, direction = 0;
    };
    VertexPairs takeVertexPairs(PixelSampler &sampler) const;
    Vec3f directLight(const SurfaceInteraction &si, const Bsdf &bsdf, const Vec3f &wo, const PixelSampler &sampler,
                      const VertexPairs &pairs, RayCounts &counts) const;
    Vec3f lightSampleContribution(const SurfaceInteraction &si, const Bsdf &bsdf, const Vec3f &wo,
                                  const LightSample &light, RayCounts &counts) const;
    // What reaches the surface from infinity along wi through glass and cut-outs.
    Vec3f transmittanceTowards(const SurfaceInteraction &si, const Vec3f &wi, RayCounts &counts) const;
    // Light from the sun and the environment along a ray that left the scene. `bsdfPdf` is
    // the density the last bounce chose it with; 0 after a delta lobe or for camera rays,
    // which no light sample could have found.
    Vec3f escapedLight(const Vec3f &direction, float bsdfPdf) const;
    // Russian roulette: whether the path goes on; if so, its throughput makes up for the others.
    bool survives(Vec3f &beta, float u) const;
    FirstHit describeFirstHit(const SurfaceInteraction &si, const Bsdf &bsdf) const;

    const RenderScene &scene_;
    const Bvh &bvh_;
    SurfaceLookup surfaces_;
    MaterialLookup materials_;
    SunLight sun_;
    EnvironmentLight environment_;
    float pixelSpread_;  // radians a pixel spans, for texture footprints (ray cones)
    Vec3f cameraForward_;
};

}  // namespace veduta
