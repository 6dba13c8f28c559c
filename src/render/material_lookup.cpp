#include "render/material_lookup.h"

#include <algorithm>

#include "render/shading_normal.h"

namespace veduta {

MaterialLookup::MaterialLookup(const RenderScene &scene) : scene_(scene) {
    anyPassThrough_ =
        std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material &m) { return m.passesLight(); });
}

void MaterialLookup::lookup(TextureId id, const Material &m, const SurfaceInteraction &si, float footprint, float *out,
                            int count) const {
    Vec2f uv{si.uv.x / m.textureSize.x, si.uv.y / m.textureSize.y};
    float width = footprint * si.uvPerMetre / std::min(m.textureSize.x, m.textureSize.y);
    float values[4] = {0, 0, 0, 0};
    int channels = std::min(scene_.textures->channels(id), 4);
    scene_.textures->lookup(id, uv, width, values, channels);
    for (int c = 0; c < count; ++c) out[c] = values[std::min(c, channels - 1)];
}

bool MaterialLookup::cutAway(const SurfaceInteraction &si, float footprint) const {
    const Material &m = scene_.materials[si.material];
    if (m.opacityMap == kNoTexture) return false;
    // A map with alpha (grey and alpha, or RGBA) cuts by its alpha, a grey or RGB one by its
    // first channel.
    float values[4];
    lookup(m.opacityMap, m, si, footprint, values, 4);
    int channels = scene_.textures->channels(m.opacityMap);
    float opacity = channels == 2 || channels == 4 ? values[channels - 1] : values[0];
    return opacity < 0.5f;
}

Vec3f MaterialLookup::shadingNormal(const Material &m, const SurfaceInteraction &si, const Vec3f &wo,
                                    float footprint) const {
    Vec3f n = si.shadingNormal;
    if (m.normalMap != kNoTexture && length(si.tangent) > 0) {
        float texel[3];
        lookup(m.normalMap, m, si, footprint, texel, 3);
        // The map is relative to the side the mesh faces; a ray from behind sees it mirrored.
        Vec3f facing = si.backFacing ? -n : n;
        Vec3f mapped =
            normalFromMap({texel[0], texel[1], texel[2]}, facing, si.tangent, si.bitangentSign, m.normalStrength);
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
    float texel[3];
    in.diffuse = m.diffuse;
    if (m.diffuseMap != kNoTexture) {
        lookup(m.diffuseMap, m, si, footprint, texel, 3);
        in.diffuse *= Vec3f(texel[0], texel[1], texel[2]);
    }
    in.specular = m.specular;
    if (m.specularMap != kNoTexture) {
        lookup(m.specularMap, m, si, footprint, texel, 1);
        in.specular *= texel[0];
    }
    in.exponent = m.shininess;
    in.mirror = m.reflectivity;
    if (m.reflectionMap != kNoTexture) {
        lookup(m.reflectionMap, m, si, footprint, texel, 1);
        in.mirror *= texel[0];
    }
    return Bsdf(in, shadingNormal(m, si, wo, footprint), si.geometricNormal);
}

Vec3f MaterialLookup::transmittance(const SurfaceInteraction &si, const Vec3f &wi, float footprint) const {
    const Material &m = scene_.materials[si.material];
    if (m.glass) return thinGlassTransmittance(std::abs(dot(wi, si.geometricNormal)), m.ior, m.glassTint);
    return cutAway(si, footprint) ? Vec3f(1.0f) : Vec3f(0.0f);
}

}  // namespace veduta
