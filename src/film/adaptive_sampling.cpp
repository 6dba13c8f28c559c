#include "film/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace veduta {

float pixelNoise(const Film &film, size_t pixel) {
    const double n = film.sampleCount(pixel), nEven = film.evenSampleCount(pixel);
    if (nEven == 0 || nEven == n) return INFINITY;
    const Vec3d all = film.radianceSum(pixel), even = film.evenRadianceSum(pixel);
    double relativeVariance = 0;
    for (auto [a, e] : {std::pair{all.x, even.x}, std::pair{all.y, even.y}, std::pair{all.z, even.z}}) {
        // The pixel's mean is (even mean + odd mean) / 2: its variance is a quarter of that of
        // their difference. Relative as relMSE weighs it.
        double mean = a / n, difference = e / nEven - (a - e) / (n - nEven);
        relativeVariance += difference * difference / 4 / (mean * mean + kRelMseEpsilon);
    }
    // relativeVariance / 3 estimates the pixel's relMSE, v / n, so this is √v / n.
    return float(std::sqrt(relativeVariance / 3 / n));
}

uint32_t adaptiveMinSamples(const RenderSettings &settings) {
    uint32_t minimum = settings.minSamples ? settings.minSamples : std::max(16u, settings.samplesPerPixel / 16);
    return std::min(minimum, settings.samplesPerPixel);
}

bool pixelNeedsSamples(const Film &film, size_t pixel, uint32_t done, uint32_t total, const RenderSettings &settings) {
    uint32_t n = film.sampleCount(pixel);
    if (n >= total) return false;
    if (settings.noiseThreshold <= 0 || n < adaptiveMinSamples(settings)) return true;
    return n == done && pixelNoise(film, pixel) >= settings.noiseThreshold;
}

uint32_t passEnd(uint32_t done, uint32_t total, uint32_t step, const RenderSettings &settings) {
    if (settings.noiseThreshold > 0) {
        uint32_t minimum = adaptiveMinSamples(settings);
        step = done < minimum ? minimum - done : kAdaptiveStep;
    }
    return std::min(total, done + std::max(step, 1u));
}

}  // namespace veduta
