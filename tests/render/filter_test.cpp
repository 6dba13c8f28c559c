#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include "render/filter.h"

namespace veduta {
namespace {

// Cycles' own window, transcribed from intern/cycles/scene/film.cpp: filter_table() doubles a
// Blackman–Harris width before it tabulates filter_func_blackman_harris(v, width) over
// [−width/2, width/2]. `width` here is the user's filter_width, so the window covers ±width.
float cyclesBlackmanHarris(float v, float filterWidth) {
    float width = 2.0f * filterWidth;
    v = 2 * float(M_PI) * (v / width + 0.5f);
    return 0.35875f - 0.48829f * std::cos(v) + 0.14128f * std::cos(2.0f * v) - 0.01168f * std::cos(3.0f * v);
}

// Pearson's χ² of sampled offsets against `density` integrated over equal bins of
// [−radius, radius], 10⁶ samples.
double chi2PValue(const PixelFilter &filter, float radius, const std::function<float(float)> &density) {
    constexpr int kBins = 60, kSamples = 1000000, kSub = 64;
    FilterSampler sampler(filter);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
    for (int s = 0; s < kSamples; ++s) {
        float x = sampler.sample({uniform(rng), 0.5f}).x;
        int bin = std::clamp(int((x + radius) / (2 * radius) * kBins), 0, kBins - 1);
        observed[size_t(bin)] += 1;
    }
    double total = 0;
    for (int b = 0; b < kBins; ++b) {
        for (int k = 0; k < kSub; ++k) {
            float x = -radius + 2 * radius * (float(b) + (float(k) + 0.5f) / kSub) / kBins;
            expected[size_t(b)] += density(x);
        }
        total += expected[size_t(b)];
    }
    double statistic = 0;
    for (int b = 0; b < kBins; ++b) {
        double e = expected[size_t(b)] / total * kSamples;
        statistic += (observed[size_t(b)] - e) * (observed[size_t(b)] - e) / e;
    }
    boost::math::chi_squared distribution(kBins - 1);
    return boost::math::cdf(boost::math::complement(distribution, statistic));
}

float uniformDensity(float) { return 1.0f; }

std::function<float(float)> cyclesWindow(float filterWidth) {
    return [filterWidth](float v) { return cyclesBlackmanHarris(v, filterWidth); };
}

// Offsets follow Cycles' window for the same filter_width: 1.5 reaches ±1.5 px.
TEST(Filter, BlackmanHarrisSamplingMatchesCyclesWindow) {
    for (float width : {1.5f, 0.75f}) {
        double p = chi2PValue({FilterKind::BlackmanHarris, width}, width, cyclesWindow(width));
        std::printf("chi2 Blackman-Harris %.2f px against Cycles' window: p = %.4f\n", width, p);
        EXPECT_GT(p, 0.01 / 3);  // Šidák over the three χ² tests of this file, to first order
    }
}

TEST(Filter, BoxSamplingIsUniform) {
    double p = chi2PValue({FilterKind::Box, 1.0f}, 0.5f, uniformDensity);
    std::printf("chi2 box 1 px: p = %.4f\n", p);
    EXPECT_GT(p, 0.01 / 3);
}

// The test can fail: Blackman–Harris samples are not uniform, and a window of half the
// width (veduta's convention before it took Cycles') is told from Cycles' one.
TEST(Filter, Chi2TellsTheWindowFromABoxAndFromHalfItsWidth) {
    EXPECT_LT(chi2PValue({FilterKind::BlackmanHarris, 1.5f}, 1.5f, uniformDensity), 1e-6);
    EXPECT_LT(chi2PValue({FilterKind::BlackmanHarris, 0.75f}, 1.5f, cyclesWindow(1.5f)), 1e-6);
}

TEST(Filter, OffsetsStayInTheSupportAndAreSymmetric) {
    FilterSampler sampler({FilterKind::BlackmanHarris, 1.5f});
    float farthest = 0;
    for (int i = 0; i <= 1000; ++i) {
        float u = float(i) / 1000;
        Vec2f o = sampler.sample({u, 1 - u});
        EXPECT_LE(std::abs(o.x), 1.5f);
        EXPECT_NEAR(o.x, -o.y, 1e-4f);
        farthest = std::max(farthest, std::abs(o.x));
    }
    EXPECT_GT(farthest, 1.49f);  // u = 0 and 1 reach the window's ends
    EXPECT_NEAR(sampler.sample({0.5f, 0.5f}).x, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace veduta
