// How much work a render does and which random choices it makes.
#pragma once

#include <cstdint>

namespace veduta {

struct RenderSettings {
    uint32_t samplesPerPixel = 16;
    uint32_t maxDepth = 8;       // path vertices after the camera; 1 = direct light only
    uint32_t seed = 0;
    uint32_t rouletteDepth = 3;  // Russian roulette starts after this many bounces
    uint32_t tileSize = 32;      // pixels; changes speed only, never the image
};

}  // namespace veduta
