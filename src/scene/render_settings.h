// How much work a render does and which random choices it makes.
#pragma once

#include <cstdint>

namespace veduta {

enum class FilterKind { Box, BlackmanHarris };

// The pixel filter; render/filter.h samples it.
struct PixelFilter {
    FilterKind kind = FilterKind::BlackmanHarris;
    // Pixels, in Cycles' convention (render/filter.h: filterRadius): a box covers ±width/2,
    // Blackman–Harris ±width. Cycles' default is Blackman–Harris 1.5.
    float width = 1.5f;
};

// Which strategies count light from the sun and the environment. Only `Mis` is for images;
// the others exist to measure what multiple importance sampling gains.
enum class LightSampling {
    Mis,    // next-event estimation and BSDF sampling, weighted by the power heuristic
    Bsdf,   // BSDF sampling only: lights are found by chance
    Light,  // next-event estimation only: light reaching a BSDF-sampled ray is ignored
};

// Russian roulette (path_tracer.cpp): from `startDepth` bounces on, a path goes on with
// probability min(1, max throughput / threshold) and its throughput is divided by it, so only
// paths that carry little (a tenth of what left the camera, by default) are thinned out.
// bench/roulette_efficiency.cpp chose the numbers; docs/performance.md has its figures.
struct Roulette {
    uint32_t startDepth = 3;
    float threshold = 0.1f;
};

struct RenderSettings {
    uint32_t samplesPerPixel = 16;
    uint32_t maxDepth = 8;  // path vertices after the camera; 1 = direct light only
    uint32_t seed = 0;
    Roulette roulette;
    uint32_t tileSize = 32;  // pixels; changes speed only, never the image
    PixelFilter filter;
    LightSampling lightSampling = LightSampling::Mis;
    // Adaptive sampling (film/adaptive_sampling.h): a pixel stops once its noise estimate falls
    // below the threshold; 0 samples every pixel fully.
    float noiseThreshold = 0;
    uint32_t minSamples = 0;  // before the first check; 0 = automatic
};

}  // namespace veduta
