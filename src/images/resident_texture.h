// A small texture held whole in memory: every mip level of its cached .tx file as floats,
// filtered like OpenImageIO's trilinear lookups (bilinear in the two levels about the
// footprint, blended), periodic, v up. OpenImageIO's TextureSystem finds each texel through a
// shared tile cache; for the 256-pixel maps of a facade library that search costs more than
// the filtering, and a district's render looks up millions of them (docs/materials.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

class ResidentTexture {
  public:
    // The texture of the .tx file (as texture_cache.h writes them), or nothing when its first
    // level has more than `maxTexels` texels or it has more than four channels. Throws
    // std::runtime_error when it cannot be read.
    static std::optional<ResidentTexture> read(const std::filesystem::path &texture, int64_t maxTexels);

    int channels() const { return channels_; }
    int64_t bytes() const;
    // As Textures::lookup: `footprint` is the filter's width in (u, v) units.
    void lookup(Vec2f uv, float footprint, float *out, int count) const;

  private:
    struct Level {
        int width = 0, height = 0;
        std::vector<float> texels;  // rows from the top, channels interleaved
    };

    void bilinear(const Level &level, float s, float t, float *out, int count) const;

    std::vector<Level> levels_;  // the finest first
    int channels_ = 0;
};

}  // namespace veduta
