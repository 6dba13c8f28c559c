#include "render/path_tracer.h"

#include <algorithm>
#include <limits>

#include "render/sampling.h"

namespace veduta {

namespace {

// After a diffuse or glossy bounce texture detail no longer shows: look textures up as if
// through a wide cone (Amanatides' ray cones, with the spread of a rough surface).
constexpr float kBouncedSpread = 0.05f;
// Cut-outs and panes a ray may pass before it counts as stuck (foliage piled on foliage).
constexpr int kMaxPassThrough = 256;

Vec3f offsetTowards(const SurfaceInteraction &si, const Vec3f &direction) {
    const Vec3f &n = si.geometricNormal;
    return offsetRayOrigin(si.position, dot(direction, n) > 0 ? n : -n);
}

bool isBlack(const Vec3f &v) { return v.x == 0 && v.y == 0 && v.z == 0; }

}  // namespace

bool PathTracer::survives(Vec3f &beta, float u) const {
    float survive = std::min(maxComponent(beta) / scene_.settings.roulette.threshold, 1.0f);
    if (u >= survive) return false;
    beta = beta / survive;
    return true;
}

PathTracer::PathTracer(const RenderScene &scene, const Bvh &bvh) :
    scene_(scene),
    bvh_(bvh),
    surfaces_(scene),
    materials_(scene),
    sun_(scene.sun),
    environment_(scene.environment),
    pixelSpread_(CameraRays(scene.camera).pixelSpread()),
    cameraForward_(scene.camera.axes().forward) {}

Vec3f PathTracer::radiance(const Ray &cameraRay, PixelSampler &sampler, RayCounts &counts, FirstHit *first) const {
    if (first) *first = FirstHit{};
    const RenderSettings &settings = scene_.settings;
    Vec3f L(0.0f), beta(1.0f);
    Ray ray = cameraRay;
    float bsdfPdf = 0;  // camera rays see lights directly
    float spread = pixelSpread_;
    float cameraDistance = 0;  // how far the camera ray went: the aerial perspective's path
    // `depth` counts the vertices that scatter; passing straight through glass is not one.
    for (uint32_t depth = 0, segment = 0; segment < settings.maxDepth + kMaxPassThrough; ++segment) {
        // The vertex's pairs, worked out only where they are used (a ray that escapes uses
        // none). Pairs for lights the scene does not sample are not taken: which ones are is
        // the same for every path, so each dimension still has one meaning.
        const VertexPairs pairs = takeVertexPairs(sampler);

        std::optional<SurfaceInteraction> si = findSurface(ray, segment == 0, spread, counts);
        if (segment == 0) cameraDistance = si ? si->distance : std::numeric_limits<float>::infinity();
        if (!si) {
            L += beta * escapedLight(ray.direction, bsdfPdf);
            break;
        }
        Vec3f wo = -ray.direction;
        Bsdf bsdf = materials_.bsdf(*si, wo, spread * si->distance);
        if (segment == 0 && first) *first = describeFirstHit(*si, bsdf);
        // The last vertex's BSDF ray was traced only for the light it finds by escaping (the
        // other half of that vertex's multiple importance sampling), through panes if need be.
        if (depth == settings.maxDepth && !bsdf.isThinGlass()) break;
        if (bsdf.hasNonDeltaLobe() && settings.lightSampling != LightSampling::Bsdf) {
            L += beta * directLight(*si, bsdf, wo, sampler, pairs, counts);
        }

        Vec2f uLobeRoulette = sampler.at(pairs.lobeRoulette);
        std::optional<BsdfSample> s = bsdf.sample(wo, uLobeRoulette.x, sampler.at(pairs.direction));
        if (!s || isBlack(s->weight)) break;
        beta *= s->weight;
        ray = {offsetTowards(*si, s->wi), s->wi};
        // Through a pane the ray keeps its density and footprint: next-event estimation at the
        // vertex before counted the same light through the pane (with its transmittance).
        if (s->passThrough) continue;
        if (depth == settings.maxDepth) break;  // a pane's reflection at the last vertex
        ++depth;
        bsdfPdf = s->delta ? 0.0f : s->pdf;
        if (!s->delta) spread = std::max(spread, kBouncedSpread);

        // Decided before the ray is traced, which is what it saves.
        if (depth >= settings.roulette.startDepth && !survives(beta, uLobeRoulette.y)) break;
    }
    // Aerial perspective on the camera ray only: light on its way to what the camera sees
    // crosses a few metres of the scene, the camera's view kilometres.
    return scene_.fog.enabled() ? scene_.fog.apply(L, cameraRay.origin, cameraRay.direction, cameraDistance) : L;
}

std::optional<SurfaceInteraction> PathTracer::findSurface(Ray ray, bool fromCamera, float footprintSpread,
                                                          RayCounts &counts) const {
    float travelled = 0;
    for (int pass = 0;; ++pass) {
        ++(fromCamera && pass == 0 ? counts.camera : counts.bounce);
        std::optional<Hit> hit = bvh_.intersect(ray, fromCamera);
        if (!hit) return std::nullopt;
        SurfaceInteraction si = surfaces_.at(*hit, ray.direction);
        si.distance += travelled;
        // Past that many cut-outs the ray is taken as stopped by the last: it must not see
        // the sky where its shadow rays see none.
        if (!materials_.anyPassThrough() || pass + 1 == kMaxPassThrough ||
            !materials_.cutAway(si, footprintSpread * si.distance)) {
            return si;
        }
        travelled = si.distance;
        ray.origin = offsetTowards(si, ray.direction);
    }
}

PathTracer::VertexPairs PathTracer::takeVertexPairs(PixelSampler &sampler) const {
    VertexPairs pairs;
    uint32_t next = sampler.take(uint32_t(sun_.enabled()) + uint32_t(environment_.sampled()) + 2);
    if (sun_.enabled()) pairs.sun = next++;
    if (environment_.sampled()) pairs.environment = next++;
    pairs.lobeRoulette = next++;
    pairs.direction = next;
    return pairs;
}

Vec3f PathTracer::directLight(const SurfaceInteraction &si, const Bsdf &bsdf, const Vec3f &wo,
                              const PixelSampler &sampler, const VertexPairs &pairs, RayCounts &counts) const {
    Vec3f L(0.0f);
    if (sun_.enabled()) L += lightSampleContribution(si, bsdf, wo, sun_.sample(sampler.at(pairs.sun)), counts);
    if (environment_.sampled())
        L += lightSampleContribution(si, bsdf, wo, environment_.sample(sampler.at(pairs.environment)), counts);
    return L;
}

Vec3f PathTracer::lightSampleContribution(const SurfaceInteraction &si, const Bsdf &bsdf, const Vec3f &wo,
                                          const LightSample &light, RayCounts &counts) const {
    Vec3f f = bsdf.eval(wo, light.wi);
    if (isBlack(f) || isBlack(light.radiance)) return Vec3f(0.0f);
    Vec3f transmitted = transmittanceTowards(si, light.wi, counts);
    if (isBlack(transmitted)) return Vec3f(0.0f);
    if (light.pdf == 0) return f * light.radiance * transmitted;  // a delta light: its irradiance
    float weight = 1;
    if (scene_.settings.lightSampling == LightSampling::Mis) weight = powerHeuristic(light.pdf, bsdf.pdf(wo, light.wi));
    return f * light.radiance * transmitted * (weight / light.pdf);
}

Vec3f PathTracer::transmittanceTowards(const SurfaceInteraction &si, const Vec3f &wi, RayCounts &counts) const {
    Ray shadow{offsetTowards(si, wi), wi};
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    if (!materials_.anyPassThrough()) {
        ++counts.shadow;
        return bvh_.occluded(shadow, kInfinity) ? Vec3f(0.0f) : Vec3f(1.0f);
    }
    // Shadow rays need no filtered texture: a narrow footprint keeps the cut-out's edge sharp.
    constexpr float kShadowFootprint = 0;
    // One occlusion query that skips the panes and cut-outs and lists them, nearest first.
    ++counts.shadow;
    // The thread's own list: Bvh::occluded empties it, and one per shadow ray would zero its
    // 32 entries each time.
    thread_local PassedSurfaces passed;
    bool stopped = bvh_.occluded(shadow, kInfinity, passed);
    Vec3f transmitted(1.0f);
    if (!passed.overflow) {
        if (stopped) return Vec3f(0.0f);
        for (uint32_t i = 0; i < passed.count && !isBlack(transmitted); ++i)
            transmitted *= materials_.transmittance(surfaces_.at(passed.hits[i], wi), wi, kShadowFootprint);
        return transmitted;
    }
    // More of them than the query holds (foliage behind foliage): surface by surface.
    for (int pass = 0; pass < kMaxPassThrough; ++pass) {
        ++counts.shadow;
        std::optional<Hit> hit = bvh_.intersect(shadow, false);
        if (!hit) return transmitted;
        SurfaceInteraction blocker = surfaces_.at(*hit, wi);
        transmitted *= materials_.transmittance(blocker, wi, kShadowFootprint);
        if (isBlack(transmitted)) break;
        shadow.origin = offsetTowards(blocker, wi);
    }
    return Vec3f(0.0f);
}

FirstHit PathTracer::firstHit(const Ray &cameraRay, RayCounts &counts) const {
    std::optional<SurfaceInteraction> si = findSurface(cameraRay, true, pixelSpread_, counts);
    if (!si) return {};
    return describeFirstHit(*si, materials_.bsdf(*si, -cameraRay.direction, pixelSpread_ * si->distance));
}

FirstHit PathTracer::describeFirstHit(const SurfaceInteraction &si, const Bsdf &bsdf) const {
    FirstHit first;
    first.hit = true;
    first.position = si.position;
    first.normal = bsdf.shadingNormal();
    first.albedo = bsdf.diffuseAlbedo();
    first.depth = dot(si.position - scene_.camera.position, cameraForward_);
    first.objectId = si.objectId;
    first.materialId = si.material + 1;
    first.buildingId = si.buildingId;
    first.instanceId = si.instanceId;
    return first;
}

Vec3f PathTracer::escapedLight(const Vec3f &direction, float bsdfPdf) const {
    Vec3f environment = environment_.radiance(direction);
    Vec3f sun = sun_.radiance(direction);
    if (bsdfPdf == 0) return environment + sun;
    switch (scene_.settings.lightSampling) {
    case LightSampling::Bsdf: return environment + sun;
    case LightSampling::Light:
        // Only what next-event estimation cannot reach: an environment it does not sample.
        return environment_.sampled() ? Vec3f(0.0f) : environment;
    case LightSampling::Mis: break;
    }
    return environment * powerHeuristic(bsdfPdf, environment_.pdf(direction)) +
        sun * powerHeuristic(bsdfPdf, sun_.pdf(direction));
}

}  // namespace veduta
