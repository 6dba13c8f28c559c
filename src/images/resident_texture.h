// A small texture held whole in memory: every mip level of its cached .tx file, or of an image
// made in memory, as floats,
// filtered like OpenImageIO's trilinear lookups (bilinear in the two levels about the
// footprint, blended), periodic, v up. OpenImageIO's TextureSystem finds each texel through a
// shared tile cache; for the 256-pixel maps of a facade library that search costs more than
// the filtering, and a district's render looks up millions of them (docs/materials.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/image.h"
#include "core/vecmath.h"

namespace veduta {

class ResidentTexture {
  public:
    // The texture of the .tx file (as texture_cache.h writes them), or nothing when its first
    // level has more than `maxTexels` texels or it has more than four channels. Throws
    // std::runtime_error when it cannot be read.
    static std::optional<ResidentTexture> read(const std::filesystem::path &texture, int64_t maxTexels);
    // The texture of a linear image of one to four channels, its mip levels each half the one
    // above (rounded down, at least 1, as maketx makes them), each texel the mean of the area of
    // the level above it covers, so that every level keeps the image's mean (maketx's box filter
    // drifts from it at odd sizes). Throws std::invalid_argument for an empty image or one of
    // more than four channels.
    static ResidentTexture fromImage(Image image);
    // The bytes fromImage would hold for an image of that size.
    static int64_t bytesFor(int width, int height, int channels);

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
