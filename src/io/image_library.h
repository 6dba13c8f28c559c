// Everything veduta does with image files in formats other than its own outputs: reading
// any format OpenImageIO reads (cubemap faces, lat-long maps, textures), writing images for
// `veduta cubemap`, and filtered texture lookups. OpenImageIO and OpenColorIO live behind
// this interface in a plugin (src/images/), loaded only when a scene or command needs it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/image.h"
#include "scene/textures.h"

namespace veduta {

class ImageLibrary {
  public:
    virtual ~ImageLibrary() = default;

    // Reads the whole image as float in linear values, converted from `colorSpace` (an
    // OpenColorIO colour space name; "" means the file's own: sRGB for 8- and 16-bit
    // integer files, linear for float files). Throws InputError naming the file.
    virtual Image read(const std::filesystem::path &file, const std::string &colorSpace) = 0;
    // Writes linear float pixels; the format follows the extension (EXR keeps floats, 8-bit
    // formats get the sRGB transfer). The file appears whole or not at all.
    virtual void write(const std::filesystem::path &file, const Image &image) = 0;
    // A texture registry whose converted files go to `cacheDirectory`.
    virtual std::shared_ptr<Textures> makeTextures(const std::filesystem::path &cacheDirectory) = 0;
};

// The image library from the plugin beside the running program; throws std::runtime_error
// saying what is missing if it cannot be loaded. Loaded once, on first use.
ImageLibrary &imageLibrary();

}  // namespace veduta
