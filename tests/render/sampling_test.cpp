#include <gtest/gtest.h>

#include "render/chi2.h"
#include "render/sampling.h"

namespace veduta {
namespace {

// Significance 1 %, Šidák-corrected over the tests of this file (pbrt-v4's choice).
constexpr int kTests = 4;
const double kAlpha = 1 - std::pow(1 - 0.01, 1.0 / kTests);

TEST(Sampling, CosineHemisphereMatchesItsDensity) {
    test::Chi2Result r =
        test::chi2Test(sampleCosineHemisphere, [](const Vec3f &d) { return cosineHemispherePdf(d.z); });
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    EXPECT_LT(r.outsideSupport, 1e-5);
}

TEST(Sampling, NarrowAndWideConesMatchTheirDensity) {
    for (float cosMax : {0.2f, 0.95f}) {
        test::Chi2Result r = test::chi2Test(
            [&](Vec2f u) { return sampleUniformCone(u, 1 - cosMax); },
            [&](const Vec3f &d) { return d.z >= cosMax ? uniformConePdf(1 - cosMax) : 0.0f; }, 1000000, 200, 40);
        EXPECT_GT(r.pValue, kAlpha) << "cosMax " << cosMax << " chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
        EXPECT_LT(r.outsideSupport, 1e-5);
    }
}

// A wrong density must fail: the test can tell a cosine lobe from a uniform hemisphere.
TEST(Sampling, Chi2RejectsAWrongDensity) {
    test::Chi2Result r = test::chi2Test(
        sampleCosineHemisphere, [](const Vec3f &d) { return d.z > 0 ? float(0.5 * kInvPi) : 0.0f; }, 200000);
    EXPECT_LT(r.pValue, 1e-6);
}

TEST(Sampling, ConcentricDiskStaysInTheDisk) {
    for (int i = 0; i <= 16; ++i) {
        for (int j = 0; j <= 16; ++j) {
            Vec2f p = sampleConcentricDisk({i / 16.0f, j / 16.0f});
            EXPECT_LE(p.x * p.x + p.y * p.y, 1.0f + 1e-6f);
        }
    }
}

}  // namespace
}  // namespace veduta
