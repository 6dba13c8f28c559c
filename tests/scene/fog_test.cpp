// The fog's transmittance against the optical depth integrated numerically, and its limits.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "scene/fog.h"

namespace veduta {
namespace {

Fog hazyAir() {
    Fog fog;
    fog.density = 2e-4f;  // about 20 km visibility at the base
    fog.baseHeight = 100;
    fog.scaleHeight = 800;
    return fog;
}

// exp(−∫ σ(z(t)) dt) by the midpoint rule over 10⁵ steps.
double numericTransmittance(const Fog &fog, Vec3f origin, Vec3f direction, double distance) {
    constexpr int kSteps = 100000;
    double depth = 0, dt = distance / kSteps;
    for (int i = 0; i < kSteps; ++i) {
        double z = origin.z + direction.z * (i + 0.5) * dt;
        depth += fog.density * std::exp(-(z - fog.baseHeight) / fog.scaleHeight) * dt;
    }
    return std::exp(-depth);
}

TEST(Fog, TransmittanceIsTheExponentialAtmospheresOpticalDepth) {
    Fog fog = hazyAir();
    for (Vec3f d : {Vec3f{1, 0, 0}, normalize(Vec3f{1, 0, 0.2f}), normalize(Vec3f{0, 1, -0.05f}),
                    normalize(Vec3f{0, 1, 1e-7f}), Vec3f{0, 0, 1}}) {
        for (float distance : {50.0f, 2000.0f, 30000.0f}) {
            Vec3f origin{0, 0, 150};
            EXPECT_NEAR(fog.transmittance(origin, d, distance), numericTransmittance(fog, origin, d, distance), 1e-5)
                << d.x << " " << d.y << " " << d.z << " over " << distance;
        }
    }
}

TEST(Fog, ToInfinity) {
    Fog fog = hazyAir();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    // Straight up, the whole column above: σ(z₀) · H.
    double column = 2e-4 * std::exp(-(150.0 - 100) / 800) * 800;
    EXPECT_NEAR(fog.transmittance({0, 0, 150}, {0, 0, 1}, kInfinity), std::exp(-column), 1e-6);
    EXPECT_EQ(fog.transmittance({0, 0, 150}, {1, 0, 0}, kInfinity), 0.0f);
    EXPECT_EQ(fog.transmittance({0, 0, 150}, normalize(Vec3f{1, 0, -0.1f}), kInfinity), 0.0f);
    EXPECT_EQ(Fog{}.transmittance({0, 0, 0}, {1, 0, 0}, kInfinity), 1.0f);  // clear air
}

// Radiance equal to the fog's own stays as it is; other radiance tends to it with distance.
TEST(Fog, ApplyBlendsTowardsTheInscatter) {
    Fog fog = hazyAir();
    fog.inscatter = Vec3f(0.5f, 0.6f, 0.8f);
    Vec3f same = fog.apply(fog.inscatter, {0, 0, 100}, {1, 0, 0}, 5000);
    EXPECT_NEAR(same.x, 0.5f, 1e-6f);
    EXPECT_NEAR(same.z, 0.8f, 1e-6f);
    float t = fog.transmittance({0, 0, 100}, {1, 0, 0}, 5000);
    EXPECT_NEAR(t, std::exp(-2e-4 * 5000), 1e-6);  // level at the base height: homogeneous
    Vec3f black = fog.apply(Vec3f(0.0f), {0, 0, 100}, {1, 0, 0}, 5000);
    EXPECT_NEAR(black.y, 0.6f * (1 - t), 1e-6f);
}

}  // namespace
}  // namespace veduta
