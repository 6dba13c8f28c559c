// Cubemaps as files: six face images, one cross image, or a lat-long image, in any format
// the image library reads. docs/cubemap.md describes the layouts and their orientation.
#pragma once

#include <filesystem>
#include <string>

#include "scene/cubemap.h"

namespace veduta {

// A file name standing for six files: `{face}` is replaced by east, west, north, south, up,
// down; `{axis}` by +x, -x, +y, -y, +z, -z.
bool isFacePattern(const std::filesystem::path &file);
std::filesystem::path faceFile(const std::filesystem::path &pattern, int face);

enum class CubemapLayout { Faces, VerticalCross, HorizontalCross, LatLong };

// Reads six faces (a pattern), or one image: lat-long when it is twice as wide as high
// (resampled to faces of `faceSize`, or a quarter of its width when 0), a cross otherwise.
// Throws InputError or LayoutError naming the file.
Cubemap readCubemap(const std::filesystem::path &file, const std::string &colorSpace, int faceSize);
// Faces need a pattern; a lat-long image is 4·size wide.
void writeCubemap(const Cubemap &cubemap, const std::filesystem::path &file, CubemapLayout layout);

}  // namespace veduta
