// Rendering a whole image: tiles spread over TBB's threads, each pixel's samples summed in a
// fixed order so that the image is bit-identical for any thread count or tile size.
#pragma once

#include "render/bvh.h"
#include "core/rgba_image.h"
#include "render/path_tracer.h"

namespace veduta {

struct RenderStats {
    RayCounts rays;
    double seconds = 0;
    uint64_t nonFiniteSamples = 0;  // samples dropped because a NaN or infinity came out
};

struct RenderOptions {
    bool showProgress = false;
};

// The scene's settings say how many samples and which tile size to use.
RgbaImage render(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options, RenderStats *stats = nullptr);

}  // namespace veduta
