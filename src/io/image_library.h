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
// saying what is missing if it cannot be loaded. Loaded once, on first use, thread-safe.
ImageLibrary &imageLibrary();

// Makes `library` the one imageLibrary() returns, instead of loading the plugin: for tests,
// which link the implementation. Call it before anything uses imageLibrary().
void setImageLibrary(std::unique_ptr<ImageLibrary> library);

// The plugin imageLibrary() loads: $VEDUTA_IMAGE_PLUGIN if set, else veduta-images.so beside
// the running program.
std::filesystem::path imagePluginPath();
// Loads the plugin `file` and creates its library; throws std::runtime_error naming the file
// and the reason. The plugin stays loaded until the process ends.
std::unique_ptr<ImageLibrary> loadImageLibrary(const std::filesystem::path &file);

// The plugin's entry point, which returns a new library owned by the caller.
inline constexpr const char *kImagePluginEntry = "vedutaCreateImageLibrary";
using CreateImageLibraryFunction = ImageLibrary *();

// Where converted textures are kept between runs: $VEDUTA_CACHE_DIR if set, else
// $XDG_CACHE_HOME/veduta/textures, else ~/.cache/veduta/textures.
std::filesystem::path defaultTextureCacheDirectory();

}  // namespace veduta
