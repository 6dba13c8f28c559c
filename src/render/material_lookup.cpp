#include "render/material_lookup.h"

#include <algorithm>

#include "scene/shading_normal.h"

namespace veduta {

namespace {

TexturePoint texturePoint(const SurfaceInteraction &si, float footprint) { return {si.uv, si.uvPerMetre, footprint}; }

}  // namespace

MaterialLookup::MaterialLookup(const RenderScene &scene) : scene_(scene), maps_(scene.textures.get()) {
    anyPassThrough_ =
        std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material &m) { return m.passesLight(); });
}

bool MaterialLookup::cutAway(const SurfaceInteraction &si, float footprint) const {
    return maps_.cutAway(scene_.materials[si.material], texturePoint(si, footprint));
}

Vec3f MaterialLookup::shadingNormal(const Material &m, const SurfaceInteraction &si, const Vec3f &wo,
                                    float footprint) const {
    Vec3f n = si.shadingNormal;
    if (m.normalMap != kNoTexture && length(si.tangent) > 0) {
        Vec3f texel = maps_.normalTexel(m, texturePoint(si, footprint));
        // The map is relative to the side the mesh faces; a ray from behind sees it mirrored.
        Vec3f facing = si.backFacing ? -n : n;
        Vec3f mapped = normalFromMap(texel, facing, si.tangent, si.bitangentSign, m.normalStrength);
        n = si.backFacing ? -mapped : mapped;
    }
    return ensureValidReflection(si.geometricNormal, wo, n);
}

Bsdf MaterialLookup::bsdf(const SurfaceInteraction &si, const Vec3f &wo, float footprint) const {
    const Material &m = scene_.materials[si.material];
    BsdfInputs in;
    if (m.glass) {
        in.thinGlass = true;
        in.ior = m.ior;
        in.glassTint = m.glassTint;
        return Bsdf(in, si.geometricNormal, si.geometricNormal);
    }
    SurfaceColors colors = maps_.colors(m, texturePoint(si, footprint));
    in.diffuse = colors.diffuse;
    in.specular = colors.specular;
    in.exponent = m.shininess;
    in.mirror = colors.mirror;
    return Bsdf(in, shadingNormal(m, si, wo, footprint), si.geometricNormal);
}

Vec3f MaterialLookup::transmittance(const SurfaceInteraction &si, const Vec3f &wi, float footprint) const {
    const Material &m = scene_.materials[si.material];
    if (m.glass) return thinGlassTransmittance(std::abs(dot(wi, si.geometricNormal)), m.ior, m.glassTint);
    return cutAway(si, footprint) ? Vec3f(1.0f) : Vec3f(0.0f);
}

}  // namespace veduta
