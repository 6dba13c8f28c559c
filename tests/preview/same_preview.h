// Whether the preview draws a scene the same on any number of threads and any tile size.
#pragma once

#include <initializer_list>

#include "preview/preview.h"

namespace veduta::test {

// Draws `scene` in each mode, with wireframe and shadows on, on one thread with 64-pixel tiles and
// on two with tiles of 1, 7 and 4096 pixels, and expects every film, depth and id image equal.
void expectSameForAnyThreadsAndTiles(const RenderScene &scene, std::initializer_list<PreviewMode> modes);

}  // namespace veduta::test
