// Filtered, mip-mapped texture lookups. Generators register image files, images they made
// (baked masonry) or textures they compute (procedural masonry) here while building a RenderScene; the renderer and the
// preview only look up. The implementation is OpenImageIO's TextureSystem, behind this interface in the image plugin
// (src/images/), so that programs that never touch a texture do not load OpenImageIO.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/image.h"
#include "core/vecmath.h"

namespace veduta {

using TextureId = uint32_t;
inline constexpr TextureId kNoTexture = ~0u;

// A texture computed where it is looked up instead of read from an image: a generator's
// procedural masonry (facade/masonry_shader.h). It defines its own (u, v) and footprint units.
class ProceduralTexture {
  public:
    virtual ~ProceduralTexture() = default;
    virtual int channels() const = 0;
    // Changes when the values would.
    virtual std::string fingerprint() const = 0;
    // Writes min(channels, count) values at (u, v), filtered over `footprint`. Thread-safe.
    virtual void lookup(Vec2f uv, float footprint, float *out, int count) const = 0;
};

class Textures {
  public:
    virtual ~Textures() = default;

    // Makes `file` ready for lookups: converts it once to a tiled, mip-mapped texture in
    // linear values (from `colorSpace`, an OpenColorIO colour space name, or "" for the
    // file's own), kept in a cache so later runs reuse it. The same file and colour space
    // give the same id. Throws InputError naming the file if it cannot be read.
    virtual TextureId add(const std::filesystem::path &file, const std::string &colorSpace) = 0;
    // Makes an image made in memory ready for lookups: linear values, one to four channels, rows
    // from the top as in Image. No file is written while it fits the registry's memory.
    virtual TextureId add(Image image) = 0;
    // Makes a procedural texture ready for lookups, which it answers itself.
    virtual TextureId add(std::shared_ptr<const ProceduralTexture> texture) = 0;
    virtual int channels(TextureId id) const = 0;
    // Changes when the texel values would: the file, its size and time, the colour space.
    virtual std::string fingerprint(TextureId id) const = 0;

    // Filtered value at texture coordinates (u, v), v growing upwards from the image's
    // bottom row, wrapping periodically; `footprint` is the width in (u, v) units of the
    // area to average over; one of 1 or more (the whole period) gives the texture's mean.
    // Writes min(channels, count) values to `out`. Thread-safe.
    virtual void lookup(TextureId id, Vec2f uv, float footprint, float *out, int count) const = 0;
};

// What a generator registers its images through, so that it needs no registry of its own: an
// image file (read in its own colour space; throws InputError naming the file when it cannot be
// read), or an image it made.
using AddTexture = std::function<TextureId(const std::filesystem::path &image)>;
using AddImage = std::function<TextureId(Image image)>;
using AddProcedural = std::function<TextureId(std::shared_ptr<const ProceduralTexture> texture)>;

}  // namespace veduta
