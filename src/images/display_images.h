// Display images: scene-linear pixels through an OpenColorIO display, view and looks, as
// oiiotool's --ociodisplay and --ociolook apply them, written as PNG, JPEG or TIFF with the
// choice recorded in the file's metadata.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/image.h"
#include "images/color_config.h"
#include "io/image_library.h"

namespace veduta {

// DisplaySettings checked against their config, with the defaults filled in.
struct DisplayChoice {
    std::shared_ptr<const ColorConfig> config;
    std::string display, view, look;
    float exposureStops = 0.0f;
};

// The settings' config (`fallback` when they name no file), display, view and looks. Throws
// InputError, placed at the config, for a config that cannot be used and for an unknown
// display, view or look, listing the names the config has.
DisplayChoice chooseDisplay(const DisplaySettings &settings, std::shared_ptr<const ColorConfig> fallback);

// The colour channels of `linear` as display values (0 to 1 on the display, not clamped);
// further channels such as alpha are copied. Throws InputError when the config cannot build
// the transform (a missing LUT file, say).
Image toDisplay(const Image &linear, const DisplayChoice &choice);

// Writes `linear` through the choice's view: PNG and JPEG with 8 bits, TIFF with 16, by the
// extension (JPEG drops alpha, which it cannot store). The metadata names the config, display,
// view, look and exposure (attributes ocioconfig, ociodisplay, ocioview, ociolook,
// ocioexposure, oiio:ColorSpace and a summary in ImageDescription). The file appears whole or
// not at all; throws std::runtime_error naming the file when it cannot be written.
void writeDisplayImageFile(const std::filesystem::path &file, const Image &linear, const DisplayChoice &choice);

}  // namespace veduta
