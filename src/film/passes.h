// A film developed into the passes compositors know, under Blender's names: one layer
// "ViewLayer" with passes "Combined", "Depth", "Normal", … and channels "R", "X", … so that
// "ViewLayer.Combined.R" opens in Blender's compositor as the render's image. docs/output.md
// lists every pass.
#pragma once

#include <string>

#include "core/layered_image.h"
#include "core/rgba_image.h"
#include "film/film.h"

namespace veduta {

inline constexpr const char *kViewLayer = "ViewLayer";
// Blender's depth for pixels that show the background.
inline constexpr float kBackgroundDepth = 1e10f;
// Ids are stored as floats, as Blender stores IndexOB; above this they would not be exact.
inline constexpr uint32_t kLargestExactId = 1u << 24;

// "ViewLayer.<pass>.<channel>"
std::string passChannel(const std::string &pass, const std::string &channel);

// Means of the accumulated passes, the first sample's data passes, the sample counts. The
// metadata is left to the caller.
LayeredImage developFilm(const Film &film);

// The Combined pass of a developed image as an RGBA picture of its data window.
RgbaImage combinedImage(const LayeredImage &image);
RgbaImage combinedImage(const Film &film);

}  // namespace veduta
