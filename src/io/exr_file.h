// Multilayer OpenEXR files, read and written with OpenEXR directly: channels with any names
// (Blender's "ViewLayer.Combined.R"), a data window inside the display window, metadata.
#pragma once

#include <filesystem>

#include "core/layered_image.h"

namespace veduta {

// Float channels, ZIP compression, the image's metadata as attributes (strings, ints,
// doubles, M44f). Encoded in memory and written atomically with every write checked, so a
// full disk gives an error naming `file` and leaves nothing under its name.
// Throws std::runtime_error naming the file.
void writeExr(const LayeredImage &image, const std::filesystem::path &file);

// Every channel as float (half and uint converted), with the file's data window and its
// string, int, float, double and M44f attributes (floats read as doubles).
// Throws std::runtime_error naming the file.
LayeredImage readExr(const std::filesystem::path &file);

}  // namespace veduta
