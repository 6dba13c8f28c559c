// The sun as next-event estimation samples it: directions uniform over the disc's cone, and
// densities that match, for the real sun's size, too small for a χ² over the whole sphere.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/distributions/chi_squared.hpp>

#include "render/lights.h"

namespace veduta {
namespace {

// Uniform over a cone means (1 − cos θ) / (1 − cos θmax) and φ about the axis are both
// uniform in [0, 1). 1 − cos θ is taken as |d − axis|² / 2, which stays exact for tiny cones.
// `binnedAs` gives the cone the samples are checked against; it is `sun` except to show that
// the test can fail.
double coneChi2PValue(const Sun &sun, const Sun &binnedAs, uint32_t seed, int samples = 1000000) {
    constexpr int rows = 20, columns = 40;
    SunLight light(sun);
    Frame frame = Frame::fromNormal(sun.direction);
    double oneMinusCosMax = binnedAs.oneMinusCosRadius();
    std::vector<double> observed(size_t(rows * columns), 0.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int s = 0; s < samples; ++s) {
        Vec3f d = light.sample({uniform(rng), uniform(rng)}).wi;
        Vec3f chord = d - sun.direction;
        double t = 0.5 * dot(chord, chord) / oneMinusCosMax;
        double phi = std::atan2(double(dot(d, frame.t)), double(dot(d, frame.s))) / (2 * M_PI) + 0.5;
        int i = std::min(int(t * rows), rows - 1), j = std::min(int(phi * columns), columns - 1);
        observed[size_t(i * columns + j)] += 1;
    }
    double expected = double(samples) / (rows * columns), statistic = 0;
    for (double o : observed) statistic += (o - expected) * (o - expected) / expected;
    boost::math::chi_squared distribution(rows * columns - 1);
    return boost::math::cdf(boost::math::complement(distribution, statistic));
}

Sun sunOf(float diameter) {
    Sun sun;
    sun.direction = Sun::directionFromAzimuthElevation(215, 38);
    sun.angularDiameterDegrees = diameter;
    return sun;
}

// Šidák over the χ² tests of this file.
constexpr int kTests = 3;
const double kAlpha = 1 - std::pow(1 - 0.01, 1.0 / kTests);

TEST(SunLight, ConeSamplesAreUniformForTheRealSun) {
    uint32_t seed = 3;  // a seed per test, so that their p-values are independent
    for (float diameter : {0.53f, 5.0f, 30.0f}) {
        double p = coneChi2PValue(sunOf(diameter), sunOf(diameter), seed++);
        std::printf("[ chi2     ] sun cone %.2f deg: p-value %.4f (alpha %.5f)\n", diameter, p, kAlpha);
        EXPECT_GT(p, kAlpha) << diameter;
    }
}

TEST(SunLight, SamplesLieInTheDiscWithItsDensity) {
    Sun sun = sunOf(0.53f);
    SunLight light(sun);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    float expectedPdf = 1.0f / (2 * kPi * sun.oneMinusCosRadius());
    for (int s = 0; s < 10000; ++s) {
        LightSample sample = light.sample({uniform(rng), uniform(rng)});
        ASSERT_TRUE(sun.discContains(sample.wi));
        EXPECT_FLOAT_EQ(sample.pdf, expectedPdf);
        EXPECT_FLOAT_EQ(light.pdf(sample.wi), expectedPdf);
        EXPECT_EQ(sample.radiance, sun.discRadiance());
    }
    // Outside the disc neither BSDF samples nor the density see it.
    Vec3f beside = Sun::directionFromAzimuthElevation(215, 38.5f);
    EXPECT_EQ(light.pdf(beside), 0.0f);
    EXPECT_EQ(light.radiance(beside), Vec3f(0.0f));
}

// The test can fail: samples of a disc checked against one of 0.9 times its diameter.
TEST(SunLight, Chi2RejectsAWrongCone) { EXPECT_LT(coneChi2PValue(sunOf(0.53f), sunOf(0.477f), 1, 200000), 1e-6); }

}  // namespace
}  // namespace veduta
