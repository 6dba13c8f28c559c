#include "render/filter.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

// Cells of the tabulated distribution over the filter's support (a 1400th of a pixel at the
// default width), and as many guide entries: a search of one or two cells but in the tails,
// and both tables in a core's first-level cache, since every camera ray reads them twice.
constexpr int kSteps = 1 << 12;
constexpr int kGuideSize = kSteps;
static_assert(kSteps <= 1 << 16, "guide entries are 16-bit cell numbers");

}  // namespace

float blackmanHarris(float x, float window) {
    if (std::abs(x) > 0.5f * window) return 0.0f;
    double t = 2 * M_PI * (double(x) / window + 0.5);
    return float(0.35875 - 0.48829 * std::cos(t) + 0.14128 * std::cos(2 * t) - 0.01168 * std::cos(3 * t));
}

float filterRadius(const PixelFilter &filter) {
    return filter.kind == FilterKind::Box ? 0.5f * filter.width : filter.width;
}

FilterSampler::FilterSampler(const PixelFilter &filter) : radius_(filterRadius(filter)) {
    if (filter.kind == FilterKind::Box) return;  // uniform: no table needed
    // The running integral of the filter by the midpoint rule, normalised.
    cdf_.assign(kSteps + 1, 0.0);
    for (int i = 0; i < kSteps; ++i) {
        float x = 2 * radius_ * ((float(i) + 0.5f) / kSteps - 0.5f);
        cdf_[size_t(i) + 1] = cdf_[size_t(i)] + blackmanHarris(x, 2 * radius_);
    }
    for (double &c : cdf_) c /= cdf_.back();
    inverseMass_.resize(kSteps);
    for (size_t i = 0; i < size_t(kSteps); ++i) {
        double mass = cdf_[i + 1] - cdf_[i];
        inverseMass_[i] = mass > 0 ? 1 / mass : 0;
    }
    guide_.resize(kGuideSize + 1);
    size_t i = 0;
    for (int k = 0; k <= kGuideSize; ++k) {
        double p = double(k) / kGuideSize;
        while (i + 1 < size_t(kSteps) && cdf_[i + 1] <= p) ++i;
        guide_[size_t(k)] = uint16_t(i);
    }
}

float FilterSampler::offset(float u) const {
    if (cdf_.empty()) return radius_ * (2 * u - 1);
    // The cell whose share of the distribution holds u, and u's place within it.
    size_t k = std::min(size_t(double(u) * kGuideSize), size_t(kGuideSize) - 1);
    // The search ends before the table's last entry, so that u = 1 lands in the last cell.
    // With as many guide entries as cells, a guide cell holds one cell on average: two steps
    // forward find it but in the tails. They are taken without branches, which the predictor
    // would miss half the time (their number is as random as u); the loop after them is for
    // the tails.
    size_t end = std::min(size_t(guide_[k + 1]) + 2, cdf_.size() - 1);
    size_t i = guide_[k];
    for (int step = 0; step < 2; ++step) i += size_t(i + 1 < end) & size_t(cdf_[i + 1] <= double(u));
    while (i + 1 < end && cdf_[i + 1] <= double(u)) ++i;
    double within = inverseMass_[i] > 0 ? std::clamp((u - cdf_[i]) * inverseMass_[i], 0.0, 1.0) : 0.5;
    return float(radius_ * (2 * (double(i) + within) / kSteps - 1));
}

}  // namespace veduta
