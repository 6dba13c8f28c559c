// The ImageLibrary of the image plugin: OpenImageIO for files and textures, OpenColorIO for
// colour spaces. Tests link it directly; the veduta program loads it from veduta-images.so.
#pragma once

#include <memory>

#include "io/image_library.h"

namespace veduta {

// Throws std::runtime_error when $OCIO names a colour configuration that cannot be read.
std::unique_ptr<ImageLibrary> makeOiioImageLibrary();

}  // namespace veduta
