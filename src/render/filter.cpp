#include "render/filter.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

constexpr int kTableSize = 1024;
constexpr int kIntegrationSteps = 16 * kTableSize;

}  // namespace

float blackmanHarris(float x, float width) {
    if (std::abs(x) > 0.5f * width) return 0.0f;
    double t = 2 * M_PI * (double(x) / width + 0.5);
    return float(0.35875 - 0.48829 * std::cos(t) + 0.14128 * std::cos(2 * t) - 0.01168 * std::cos(3 * t));
}

FilterSampler::FilterSampler(const PixelFilter &filter) : width_(filter.width) {
    if (filter.kind == FilterKind::Box) return;  // uniform: no table needed
    // Integrate the filter with the midpoint rule, then invert the running sum by walking it.
    std::vector<double> cdf(kIntegrationSteps + 1, 0.0);
    for (int i = 0; i < kIntegrationSteps; ++i) {
        float x = width_ * ((float(i) + 0.5f) / kIntegrationSteps - 0.5f);
        cdf[size_t(i) + 1] = cdf[size_t(i)] + blackmanHarris(x, width_);
    }
    for (double &c : cdf) c /= cdf.back();
    inverseCdf_.resize(kTableSize + 1);
    int i = 0;
    for (int k = 0; k <= kTableSize; ++k) {
        double p = double(k) / kTableSize;
        while (i < kIntegrationSteps - 1 && cdf[size_t(i) + 1] < p) ++i;
        double span = cdf[size_t(i) + 1] - cdf[size_t(i)];
        double within = span > 0 ? std::clamp((p - cdf[size_t(i)]) / span, 0.0, 1.0) : 0.0;
        inverseCdf_[size_t(k)] = float(width_ * ((i + within) / kIntegrationSteps - 0.5));
    }
}

float FilterSampler::offset(float u) const {
    if (inverseCdf_.empty()) return width_ * (u - 0.5f);
    float position = u * kTableSize;
    int k = std::min(int(position), kTableSize - 1);
    float t = position - float(k);
    return inverseCdf_[size_t(k)] * (1 - t) + inverseCdf_[size_t(k) + 1] * t;
}

}  // namespace veduta
