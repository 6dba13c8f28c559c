// A material's maps read at a point of a surface: filtered, mip-mapped lookups over the area a
// pixel covers there. The path tracer (MaterialLookup) and the preview both read maps through
// this, so that both show the same texels for the same footprint.
#pragma once

#include "scene/material.h"
#include "scene/textures.h"

namespace veduta {

// Where on a surface the maps are read.
struct TexturePoint {
    Vec2f uv;              // the mesh's texture coordinates, before the material's textureSize
    float uvPerMetre = 0;  // how fast (u, v) changes over the surface
    float footprint = 0;   // width in metres of the area a lookup averages
};

// A Phong material's colours at a point, each times its map; lobeWeights balances them.
struct SurfaceColors {
    Vec3f diffuse, specular, mirror;
};

class MaterialMaps {
  public:
    // `textures` may be null when no material has maps.
    explicit MaterialMaps(const Textures *textures) : textures_(textures) {}

    // A map's value at the point; `count` channels, missing ones repeat the last.
    void lookup(TextureId id, const Material &m, const TexturePoint &at, float *out, int count) const;
    // k_d, k_s and the mirror's reflectivity times their maps (unused for glass).
    SurfaceColors colors(const Material &m, const TexturePoint &at) const;
    // Whether a cut-out removes the surface at the point.
    bool cutAway(const Material &m, const TexturePoint &at) const;
    // The normal map's texel, each channel in [0, 1]; the material must have a normal map.
    Vec3f normalTexel(const Material &m, const TexturePoint &at) const;

  private:
    const Textures *textures_;
};

}  // namespace veduta
