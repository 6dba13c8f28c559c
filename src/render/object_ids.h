// Which object each pixel shows, as the path tracer sees it: the object id of what the camera ray
// through the pixel centre meets, cut-outs passed through as in its id pass (0 for the
// background). The preview's id mode must agree.
#pragma once

#include <cstdint>
#include <vector>

#include "render/bvh.h"

namespace veduta {

std::vector<uint32_t> objectIdsAtPixelCentres(const RenderScene &scene, const Bvh &bvh);

}  // namespace veduta
