// What a render has done so far: with the film, all a resumed render needs. Here rather than
// beside the renderer because checkpoints (src/io) read and write it and may not see src/render.
#pragma once

#include <cstdint>

namespace veduta {

struct RayCounts {
    uint64_t camera = 0;
    uint64_t bounce = 0;
    uint64_t shadow = 0;

    uint64_t total() const { return camera + bounce + shadow; }
    RayCounts &operator+=(const RayCounts &o) {
        camera += o.camera;
        bounce += o.bounce;
        shadow += o.shadow;
        return *this;
    }
};

struct RenderStats {
    uint32_t samplesDone = 0;  // passes completed: no pixel has more samples than this
    RayCounts rays;
    double seconds = 0;
    uint64_t nonFiniteSamples = 0;  // samples that came out NaN or infinite, counted as black
};

}  // namespace veduta
