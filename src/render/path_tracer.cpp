#include "render/path_tracer.h"

#include <algorithm>
#include <limits>

#include "render/sampling.h"

namespace veduta {

PathTracer::PathTracer(const RenderScene &scene, const Bvh &bvh)
    : scene_(scene), bvh_(bvh), surfaces_(scene), sunIsDisc_(scene.sun.angularDiameterDegrees > 0),
      sunOneMinusCosRadius_(scene.sun.oneMinusCosRadius()), sunFrame_(Frame::fromNormal(scene.sun.direction)),
      sunDiscRadiance_(sunIsDisc_ ? scene.sun.discRadiance() : Vec3f(0.0f)),
      sunIncidentPerSample_(sunIsDisc_ ? sunDiscRadiance_ / uniformConePdf(sunOneMinusCosRadius_) : scene.sun.irradiance) {}

Vec3f PathTracer::radiance(const Ray &cameraRay, PixelSampler &sampler, RayCounts &counts) const {
    const RenderSettings &settings = scene_.settings;
    Vec3f L(0.0f), beta(1.0f);
    Ray ray = cameraRay;
    for (uint32_t depth = 0;; ++depth) {
        bool fromCamera = depth == 0;
        ++(fromCamera ? counts.camera : counts.bounce);
        std::optional<Hit> hit = bvh_.intersect(ray, fromCamera);
        if (!hit) {
            L += beta * escapedRadiance(ray, fromCamera);
            break;
        }
        SurfaceInteraction si = surfaces_.at(*hit, ray.direction);
        Vec3f albedo = scene_.materials[si.material].diffuse;

        Vec2f uLight = sampler.next2D();
        if (scene_.sun.enabled()) L += beta * sunLight(si, albedo, uLight, counts);
        if (depth + 1 >= settings.maxDepth) break;

        // Lambertian BSDF sampled by cosine: f·cos/pdf is the albedo.
        Vec3f wi = Frame::fromNormal(si.shadingNormal).toWorld(sampleCosineHemisphere(sampler.next2D()));
        if (dot(wi, si.geometricNormal) <= 0) break;  // the shading normal points below the surface
        beta *= albedo;

        float uRoulette = sampler.next1D();
        if (depth + 1 >= settings.rouletteDepth) {
            float survive = std::min(maxComponent(beta), 0.95f);
            if (uRoulette >= survive) break;
            beta = beta / survive;
        }
        ray = {offsetRayOrigin(si.position, si.geometricNormal), wi};
    }
    return L;
}

Vec3f PathTracer::sunLight(const SurfaceInteraction &si, const Vec3f &albedo, Vec2f u, RayCounts &counts) const {
    Vec3f wi = sunIsDisc_ ? sunFrame_.toWorld(sampleUniformCone(u, sunOneMinusCosRadius_)) : scene_.sun.direction;
    float cosTheta = dot(si.shadingNormal, wi);
    if (cosTheta <= 0 || dot(si.geometricNormal, wi) <= 0) return Vec3f(0.0f);

    ++counts.shadow;
    Ray shadow{offsetRayOrigin(si.position, si.geometricNormal), wi};
    if (bvh_.occluded(shadow, std::numeric_limits<float>::infinity())) return Vec3f(0.0f);
    return albedo * kInvPi * cosTheta * sunIncidentPerSample_;
}

// Light from outside the scene. The sun disc counts only for camera rays: for every later
// vertex next-event estimation has already counted it.
Vec3f PathTracer::escapedRadiance(const Ray &ray, bool cameraRay) const {
    Vec3f L = scene_.environment.radianceTowards(ray.direction);
    if (cameraRay && sunIsDisc_ && scene_.sun.discContains(ray.direction)) L += sunDiscRadiance_;
    return L;
}

}  // namespace veduta
