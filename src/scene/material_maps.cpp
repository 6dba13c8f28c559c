#include "scene/material_maps.h"

#include <algorithm>

namespace veduta {

void MaterialMaps::lookup(TextureId id, const Material &m, const TexturePoint &at, float *out, int count) const {
    Vec2f uv{at.uv.x / m.textureSize.x, at.uv.y / m.textureSize.y};
    float width = at.footprint * at.uvPerMetre / std::min(m.textureSize.x, m.textureSize.y);
    float values[4] = {0, 0, 0, 0};
    int channels = std::min(textures_->channels(id), 4);
    textures_->lookup(id, uv, width, values, channels);
    for (int c = 0; c < count; ++c) out[c] = values[std::min(c, channels - 1)];
}

SurfaceColors MaterialMaps::colors(const Material &m, const TexturePoint &at) const {
    SurfaceColors colors{m.diffuse, m.specular, m.reflectivity};
    float texel[3];
    if (m.diffuseMap != kNoTexture) {
        lookup(m.diffuseMap, m, at, texel, 3);
        colors.diffuse *= Vec3f(texel[0], texel[1], texel[2]);
    }
    if (m.specularMap != kNoTexture) {
        lookup(m.specularMap, m, at, texel, 1);
        colors.specular *= texel[0];
    }
    if (m.reflectionMap != kNoTexture) {
        lookup(m.reflectionMap, m, at, texel, 1);
        colors.mirror *= texel[0];
    }
    return colors;
}

bool MaterialMaps::cutAway(const Material &m, const TexturePoint &at) const {
    if (m.opacityMap == kNoTexture) return false;
    // A map with alpha (grey and alpha, or RGBA) cuts by its alpha, a grey or RGB one by its
    // first channel.
    float values[4];
    lookup(m.opacityMap, m, at, values, 4);
    int channels = textures_->channels(m.opacityMap);
    float opacity = channels == 2 || channels == 4 ? values[channels - 1] : values[0];
    return opacity < 0.5f;
}

Vec3f MaterialMaps::normalTexel(const Material &m, const TexturePoint &at) const {
    float texel[3];
    lookup(m.normalMap, m, at, texel, 3);
    return {texel[0], texel[1], texel[2]};
}

}  // namespace veduta
