// Compiled only by the ctest `layers_reject_build`, which passes when this does NOT compile:
// src/geo may not include src/render (docs/ARCHITECTURE.md, Layers), so the renderer's headers
// are not on the geo library's include path.
#include "geo/atkis.h"
#include "render/bvh.h"
