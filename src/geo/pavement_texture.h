// The surface of a pavement (geo/road_style.h) computed where it is looked up: asphalt with its
// aggregate and wear (seed 004: Perlin, 4 octaves, persistence 0.55), setts in rows with joints,
// concrete slabs, gravel and ballast as cells (cellular noise, d2 − d1 for the stones' edges,
// the seed's "d1 − d0") with the sleepers and rails of a track. (u, v) are metres of the ribbon:
// u to the right of its centre line, v along it (a material reads the ribbon's tile units with
// textureSize 1 / tile length). The footprint is metres too: pattern finer than it gives way to
// its mean, so a road reads right from 1 m to kilometres away. docs/roads.md.
#pragma once

#include <cstdint>
#include <string>

#include "geo/road_style.h"
#include "scene/textures.h"

namespace veduta {

enum class PavementMap {
    Colour,  // linear RGB albedo, to multiply the material's diffuse colour (white)
    Normal,  // tangent-space normal, OpenGL convention, as a normal map's texels in [0, 1]
};

class PavementTexture : public ProceduralTexture {
  public:
    // `tracks`: for ballast, the tracks laid on it, side by side 4.5 m apart about the centre.
    PavementTexture(Pavement pavement, PavementMap map, uint32_t seed, int tracks = 1);

    int channels() const override { return 3; }
    std::string fingerprint() const override;
    void lookup(Vec2f uv, float footprint, float *out, int count) const override;

  private:
    Pavement pavement_;
    PavementMap map_;
    uint32_t seed_;
    int tracks_;
};

}  // namespace veduta
