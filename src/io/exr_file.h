// Multilayer OpenEXR files, read and written with OpenEXR directly: channels with any names
// (Blender's "ViewLayer.Combined.R"), a data window inside the display window, metadata.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/layered_image.h"

namespace veduta {

// OpenEXR's codecs, under OpenEXR's names.
enum class ExrCompression { None, Rle, Zips, Zip, Piz, Pxr24, B44, B44a, Dwaa, Dwab };

// How the channels are stored: the codec, and which channels are half floats (the rest are
// 32-bit floats).
struct ExrFormat {
    ExrCompression compression = ExrCompression::Zip;
    std::set<std::string> halfChannels;
};

// "none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab".
const std::vector<std::string> &exrCompressionNames();
std::string_view exrCompressionName(ExrCompression compression);
std::optional<ExrCompression> exrCompressionNamed(std::string_view name);
// Whether the codec may change 32-bit float values: pxr24 rounds them to 24 bits, dwaa and
// dwab quantize channels named R, G, B, Y (whatever their layer). b44 and b44a store 32-bit
// channels unchanged but change half ones.
bool changesFloatChannels(ExrCompression compression);

// The channels as `format` says, the image's metadata as attributes (strings, ints, doubles,
// M44f) and the chromaticities of linear Rec.709 (D65), which veduta renders in. Encoded in
// memory and written atomically with every write checked, so a full disk gives an error naming
// `file` and leaves nothing under its name. Throws std::runtime_error naming the file.
void writeExr(const LayeredImage &image, const std::filesystem::path &file, const ExrFormat &format = {});

// Every channel as float (half and uint converted), with the file's data window and its
// string, int, float, double and M44f attributes (floats read as doubles); `format`, if given,
// receives how the file stores them. Throws std::runtime_error naming the file.
LayeredImage readExr(const std::filesystem::path &file, ExrFormat *format = nullptr);

}  // namespace veduta
