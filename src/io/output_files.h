// Writing RGBA images to files: scene-linear float EXR, and an 8-bit sRGB PNG for a quick look.
// Each file is written under a temporary name beside its target and renamed when complete,
// so a failed or interrupted run never leaves a damaged file or destroys an older good one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/rgba_image.h"

namespace veduta {

// RGBA float, ZIP compression, channel names R G B A.
void writeExr(const RgbaImage &film, const std::filesystem::path &file);
// Plain sRGB transfer function, clamped to [0, 1]; OCIO display transforms come later.
void writePng(const RgbaImage &film, const std::filesystem::path &file);
// 8-bit pixels already encoded (`channels` 3: RGB, 4: RGBA, top row first), written as they
// are; what writePng and the diff image write through. Throws std::runtime_error naming the file.
void writeEncodedPng(const std::vector<uint8_t> &pixels, int width, int height, int channels,
                     const std::filesystem::path &file);
// The same, as the bytes of a PNG file in memory (for reports that carry their images).
// Throws std::runtime_error with libpng's message.
std::vector<unsigned char> encodePng(const std::vector<uint8_t> &pixels, int width, int height, int channels);
// The image's 8-bit sRGB RGBA pixels, as writePng writes them.
std::vector<uint8_t> srgbPixels(const RgbaImage &film);

float linearToSrgb(float linear);

// Creates the folders of `file` and checks that a file can be written there, so that a long
// render does not end in an error it could have reported at the start. Throws
// std::runtime_error naming the file.
void prepareOutputFile(const std::filesystem::path &file);

}  // namespace veduta
