// A film developed into the passes compositors know, under Blender's names: one layer
// "ViewLayer" with passes "Combined", "Depth", "Normal", … and channels "R", "X", … so that
// "ViewLayer.Combined.R" opens in Blender's compositor as the render's image. docs/output.md
// lists every pass.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/layered_image.h"
#include "core/rgba_image.h"
#include "film/cryptomatte.h"
#include "film/film.h"

namespace veduta {

inline constexpr const char *kViewLayer = "ViewLayer";
// Blender's depth for pixels that show the background.
inline constexpr float kBackgroundDepth = 1e10f;
// Ids are stored as floats, as Blender stores IndexOB; above this they would not be exact.
inline constexpr uint32_t kLargestExactId = 1u << 24;

// "ViewLayer.<pass>.<channel>"
std::string passChannel(const std::string &pass, const std::string &channel);

// Every pass developFilm can write, in the order docs/output.md lists them: the film's passes,
// then CryptoObject and CryptoMaterial.
const std::vector<std::string> &allPasses();
// What a render writes unless told otherwise: every pass but Cryptomatte's.
std::vector<std::string> defaultPasses();
// "Combined,Depth" or "all" as pass names, each once. Throws std::invalid_argument naming the
// valid names for an unknown one.
std::vector<std::string> parsePassList(const std::string &list);
// Whether a channel holds data rather than colour: depth, positions, ids, counts and
// Cryptomatte, which half floats or lossy codecs would change (an id above 2048 is not exact in
// half). Top-level R, G, B, A (--rgba) are colour.
bool isDataChannel(std::string_view channel);

struct DevelopOptions {
    std::vector<std::string> passes = defaultPasses();
    // The Combined pass also as top-level R, G, B, A, which simple viewers and `oiiotool --ch`
    // find.
    bool rgba = false;
    // Names for Cryptomatte's ids; needed when its passes are asked for.
    CryptomatteNaming naming;
};

// Means of the accumulated passes, the first sample's data passes, the sample counts, the
// Cryptomatte layers with their header entries. Other metadata is left to the caller.
LayeredImage developFilm(const Film &film, const DevelopOptions &options = {});

// The Combined pass of a developed image as an RGBA picture of its data window.
RgbaImage combinedImage(const LayeredImage &image);
RgbaImage combinedImage(const Film &film);

}  // namespace veduta
