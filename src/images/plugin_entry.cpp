// The entry point of veduta-images.so, which the veduta program loads with dlopen when a scene
// or command needs image files (src/io/image_library.cpp); the only symbol the plugin exports.
#include <type_traits>

#include "images/oiio_image_library.h"

extern "C" __attribute__((visibility("default"))) veduta::ImageLibrary *vedutaCreateImageLibrary() {
    return veduta::makeOiioImageLibrary().release();
}

static_assert(std::is_same_v<decltype(vedutaCreateImageLibrary), veduta::CreateImageLibraryFunction>,
              "the entry point must match what src/io/image_library.cpp looks up");
