// Everything veduta does with image files in formats other than its own outputs: reading
// any format OpenImageIO reads (cubemap faces, lat-long maps, textures), writing images for
// `veduta cubemap`, display images through an OpenColorIO view, and filtered texture lookups.
// OpenImageIO and OpenColorIO live behind this interface in a plugin (src/images/), loaded
// only when a scene or command needs it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/image.h"
#include "scene/textures.h"

namespace veduta {

// How scene-linear pixels become a display image, with the names of oiiotool's --ociodisplay
// and --ociolook. Empty names mean the config's defaults.
struct DisplaySettings {
    std::filesystem::path config;  // an OpenColorIO config file; "" = $OCIO, else veduta's built-in one
    std::string display;           // "" = the config's default display
    std::string view;              // "" = the display's default view
    std::string look;              // "" = none; else look names separated by commas
    float exposureStops = 0.0f;    // scene-linear values are scaled by 2^stops before the view, as Blender does
};

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
    // Writes linear RGB(A) pixels as a display image through the settings' view: PNG or JPEG
    // with 8 bits, TIFF with 16, by the extension; alpha is kept as it is. The metadata records
    // the config, display, view, look and exposure. The file appears whole or not at all.
    // Throws InputError for settings checkDisplaySettings refuses, std::runtime_error naming
    // the file when it cannot be written.
    virtual void writeDisplayImage(const std::filesystem::path &file, const Image &linear,
                                   const DisplaySettings &settings) = 0;
    // Checks the settings without an image, so that a command can refuse them before it renders:
    // throws InputError for a config that cannot be read and for an unknown display, view or
    // look, listing the names the config has.
    virtual void checkDisplaySettings(const DisplaySettings &settings) = 0;
    // A texture registry whose converted files go to `cacheDirectory`.
    virtual std::shared_ptr<Textures> makeTextures(const std::filesystem::path &cacheDirectory) = 0;
};

// The image library from the plugin beside the running program; throws std::runtime_error
// saying what is missing if it cannot be loaded. Loaded once, on first use, thread-safe.
ImageLibrary &imageLibrary();

// Makes `library` the one imageLibrary() returns, instead of loading the plugin: for tests,
// which link the implementation. Call it before anything uses imageLibrary().
void setImageLibrary(std::unique_ptr<ImageLibrary> library);

// The plugin imageLibrary() loads: $VEDUTA_IMAGE_PLUGIN if set, else veduta-images.so in the
// first folder of ProgramPart::Helper that holds it (beside the program, then ../lib/veduta).
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
