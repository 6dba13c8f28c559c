// The display image of `veduta render`: --image FILE (PNG, JPEG or TIFF) with --display,
// --view, --look, --exposure and --ocio-config, named and behaving like oiiotool's
// --ociodisplay. The film goes through the OpenColorIO view in the image plugin, which is
// loaded only when an image is asked for.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "core/image.h"
#include "core/rgba_image.h"
#include "io/image_library.h"

namespace veduta {

struct DisplayImageOptions {
    std::string file;  // "" = no display image
    DisplaySettings settings;
};

// Registers the options on `command`; the display settings need --image.
void addDisplayOptions(CLI::App &command, DisplayImageOptions &options);

// Checks, before rendering, that the image can be written and that the config, display, view and
// looks exist. Throws InputError for unknown names, std::runtime_error for an unwritable file.
void checkDisplayOptions(const DisplayImageOptions &options);

// Writes the film as the display image, if one was asked for.
void writeDisplayImage(const RgbaImage &film, const DisplayImageOptions &options);

// The film's linear RGBA pixels as an Image.
Image filmImage(const RgbaImage &film);

}  // namespace veduta
