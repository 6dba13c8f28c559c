// Reading and writing image files through OpenImageIO, with colour conversion through the
// ColorConfig: what the image plugin's read and write do, and what textures are made from.
#pragma once

#include <filesystem>
#include <string>

#include <OpenImageIO/imageio.h>

#include "core/image.h"
#include "images/color_config.h"

namespace veduta {

// The header of the file's first subimage. Throws InputError naming the file.
OIIO::ImageSpec readImageSpec(const std::filesystem::path &file);

// The colour space the pixels of `file` are in, by its config name: `requested` when given,
// else the one the file's metadata (oiio:ColorSpace) names if the config knows it, else linear
// for float files and sRGB for integer ones. Throws InputError for a name the config lacks.
std::string fileColorSpace(const std::filesystem::path &file, const OIIO::ImageSpec &spec, const std::string &requested,
                           const ColorConfig &config);

// The first subimage's full-resolution pixels as float, all channels, converted from the
// file's colour space (see fileColorSpace) to linear. Throws InputError naming the file.
Image readImageFile(const std::filesystem::path &file, const std::string &colorSpace, const ColorConfig &config);

// Writes linear pixels in the format the extension names: EXR (float, ZIP) and HDR keep
// floats, other formats get 8 bits with the sRGB transfer. The file appears whole or not at
// all; throws std::runtime_error naming the file when it cannot be written.
void writeImageFile(const std::filesystem::path &file, const Image &image, const ColorConfig &config);

// Writes pixels already in the file's encoding (0 to 1 for integer formats) as `spec` says
// (size, channels, data type, metadata), alpha unassociated. The file appears whole or not at
// all; throws std::runtime_error naming the file when it cannot be written.
void writeEncodedImage(const std::filesystem::path &file, const Image &encoded, OIIO::ImageSpec spec);

}  // namespace veduta
