#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include "render/filter.h"

namespace veduta {
namespace {

// Pearson's χ² of sampled offsets against the filter integrated over equal bins, 10⁶ samples.
double chi2PValue(const PixelFilter &filter, float (*density)(float, float)) {
    constexpr int kBins = 60, kSamples = 1000000, kSub = 64;
    FilterSampler sampler(filter);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
    float half = 0.5f * filter.width;
    for (int s = 0; s < kSamples; ++s) {
        float x = sampler.sample({uniform(rng), 0.5f}).x;
        int bin = std::clamp(int((x + half) / filter.width * kBins), 0, kBins - 1);
        observed[size_t(bin)] += 1;
    }
    double total = 0;
    for (int b = 0; b < kBins; ++b) {
        for (int k = 0; k < kSub; ++k) {
            float x = -half + filter.width * (float(b) + (float(k) + 0.5f) / kSub) / kBins;
            expected[size_t(b)] += density(x, filter.width);
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

float uniformDensity(float, float) { return 1.0f; }

TEST(Filter, BlackmanHarrisSamplingMatchesTheWindow) {
    double p = chi2PValue({FilterKind::BlackmanHarris, 1.5f}, blackmanHarris);
    std::printf("chi2 Blackman-Harris 1.5 px: p = %.4f\n", p);
    EXPECT_GT(p, 0.01 / 2);  // Šidák over the two χ² tests of this file, to first order
}

TEST(Filter, BoxSamplingIsUniform) {
    double p = chi2PValue({FilterKind::Box, 1.0f}, uniformDensity);
    std::printf("chi2 box 1 px: p = %.4f\n", p);
    EXPECT_GT(p, 0.01 / 2);
}

// The test can fail: Blackman–Harris samples are not uniform.
TEST(Filter, Chi2TellsTheWindowFromABox) {
    EXPECT_LT(chi2PValue({FilterKind::BlackmanHarris, 1.5f}, uniformDensity), 1e-6);
}

TEST(Filter, OffsetsStayInTheSupportAndAreSymmetric) {
    FilterSampler sampler({FilterKind::BlackmanHarris, 1.5f});
    for (int i = 0; i <= 1000; ++i) {
        float u = float(i) / 1000;
        Vec2f o = sampler.sample({u, 1 - u});
        EXPECT_LE(std::abs(o.x), 0.75f);
        EXPECT_NEAR(o.x, -o.y, 1e-4f);
    }
    EXPECT_NEAR(sampler.sample({0.5f, 0.5f}).x, 0.0f, 1e-6f);
}

}  // namespace
}  // namespace veduta
