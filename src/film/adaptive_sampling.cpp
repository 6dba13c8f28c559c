#include "film/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace veduta {

float pixelNoise(const Film &film, size_t pixel) {
    uint32_t n = film.sampleCount(pixel);
    if (n < 2) return INFINITY;
    Vec3d all = film.radianceSum(pixel), even = film.evenRadianceSum(pixel);
    // Cycles' "I − A" with A twice the even half: the odd half minus the even half, per sample.
    double difference =
        std::abs(all.x - 2 * even.x) + std::abs(all.y - 2 * even.y) + std::abs(all.z - 2 * even.z);
    double intensity = (all.x + all.y + all.z) / n;
    return float(difference / n / (1e-4 + std::sqrt(std::max(intensity, 0.0))));
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
