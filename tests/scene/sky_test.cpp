#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scene/sky.h"
#include "scene/sun.h"

namespace veduta {
namespace {

// Rec.709 luminance with the coefficients of the sRGB standard's RGB → XYZ matrix.
double luminance(const Vec3f &c) { return 0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z; }

double angleDegrees(const Vec3f &a, const Vec3f &b) {
    return std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)) * 180 / M_PI;
}

template <typename F>
void forEachTexel(const Cubemap &map, F &&f) {
    for (int face = 0; face < kCubeFaceCount; ++face)
        for (int y = 0; y < map.size(); ++y)
            for (int x = 0; x < map.size(); ++x)
                f(map.texel(face, x, y), map.direction(face, float(x) + 0.5f, float(y) + 0.5f), x, y);
}

// Irradiance on an upward-facing surface from the sky texels alone (those above the horizon).
Vec3f skyIrradiance(const Cubemap &map) {
    double sum[3] = {0, 0, 0};
    forEachTexel(map, [&](const Vec3f &L, const Vec3f &d, int x, int y) {
        if (d.z <= 0) return;
        for (int c = 0; c < 3; ++c) sum[c] += double(L[c]) * d.z * map.texelSolidAngle(x, y);
    });
    return {float(sum[0]), float(sum[1]), float(sum[2])};
}

const Vec3f kSunIrradiance{3.0f};

TEST(Sky, ZenithLuminanceFollowsPreethamsFormula) {
    // Preetham et al. 1999, appendix A.2, by hand for T = 3, θ_s = 30°:
    // χ = (4/9 − 3/120)(π − π/3) = 0.878482; Y_z = (4.0453·3 − 4.9710)·tan χ − 0.2155·3 + 2.4192.
    EXPECT_NEAR(preethamZenithLuminance(M_PI / 6, 3), 10.413087, 1e-5);
    // Kasten-Young air mass at 60°: 1.153992; 133.8 klx · exp(−3·m / (9.9 + 0.043·m)).
    EXPECT_NEAR(sunDirectNormalIlluminance(60, 3), 94.480698, 1e-5);

    // An odd face size puts the centre of the up face's middle texel on the zenith.
    SkySettings settings;
    settings.faceSize = 33;
    Cubemap sky = bakePreethamSky(Sun::directionFromAzimuthElevation(135, 60), kSunIrradiance, settings);
    Vec3f zenith = sky.texel(kUp, 16, 16);
    ASSERT_NEAR(sky.direction(kUp, 16.5f, 16.5f).z, 1, 1e-6);
    double expected =
        preethamZenithLuminance(M_PI / 6, 3) * luminance(kSunIrradiance) / sunDirectNormalIlluminance(60, 3);
    std::printf("zenith luminance %.6f, expected Y_z %.4f kcd/m2 * 3 / E_sun %.4f klx = %.6f\n", luminance(zenith),
                preethamZenithLuminance(M_PI / 6, 3), sunDirectNormalIlluminance(60, 3), expected);
    EXPECT_NEAR(luminance(zenith), expected, 1e-5 * expected);
    // A high sun's zenith is blue.
    std::printf("zenith RGB %.4f %.4f %.4f\n", zenith.x, zenith.y, zenith.z);
    EXPECT_GT(zenith.z, zenith.x);
}

TEST(Sky, BrightestAtTheSunAndDarkestAQuarterTurnAway) {
    Vec3f sun = Sun::directionFromAzimuthElevation(135, 60);
    Cubemap sky = bakePreethamSky(sun, kSunIrradiance, SkySettings{});
    double brightest = 0, darkest = 1e30;
    Vec3f brightestDirection, darkestDirection;
    forEachTexel(sky, [&](const Vec3f &L, const Vec3f &d, int, int) {
        if (d.z <= 0) return;
        if (luminance(L) > brightest) brightest = luminance(L), brightestDirection = d;
        if (luminance(L) < darkest) darkest = luminance(L), darkestDirection = d;
    });
    double toBrightest = angleDegrees(brightestDirection, sun), toDarkest = angleDegrees(darkestDirection, sun);
    std::printf("brightest %.4f at %.2f deg from the sun; darkest %.4f at %.2f deg from the sun, elevation %.1f\n",
                brightest, toBrightest, darkest, toDarkest, std::asin(darkestDirection.z) * 180 / M_PI);
    // The circumsolar term falls off faster than the horizon term rises, so the maximum is
    // the texel nearest the sun: within a texel's diagonal (64 per face: up to 2°).
    EXPECT_LT(toBrightest, 2.0);
    EXPECT_NEAR(toDarkest, 90, 15);
    EXPECT_GT(brightest, 4 * darkest);
}

TEST(Sky, SymmetricAboutTheSunsVerticalPlane) {
    // The sun to the south-east: the plane through it and the zenith has the horizontal
    // normal n = (1, 1, 0)/√2, and mirroring in it maps the cube's texel grid onto itself.
    Vec3f sun = Sun::directionFromAzimuthElevation(135, 35);
    SkySettings settings;
    settings.faceSize = 16;
    Cubemap sky = bakePreethamSky(sun, kSunIrradiance, settings);
    Vec3f n = normalize(Vec3f{1, 1, 0});
    double worst = 0;
    int compared = 0;
    forEachTexel(sky, [&](const Vec3f &L, const Vec3f &d, int, int) {
        Vec3f mirrored = d - n * (2 * dot(d, n));
        double nearest = 1e30;
        Vec3f other;
        forEachTexel(sky, [&](const Vec3f &L2, const Vec3f &d2, int, int) {
            double distance = length(d2 - mirrored);
            if (distance < nearest) nearest = distance, other = L2;
        });
        ASSERT_LT(nearest, 1e-5);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(double(L[c]) - other[c]) / std::max(1e-6, double(L[c])));
        ++compared;
    });
    std::printf("%d texels against their mirror images: largest relative difference %.2e\n", compared, worst);
    EXPECT_LT(worst, 1e-4);
    // The sun lies in the plane; a sky that ignored it would be symmetric about any plane.
    EXPECT_NEAR(dot(sun, n), 0, 1e-6);
}

TEST(Sky, ReddensAsTheSunSets) {
    double previous = 0;
    for (float elevation : {70.0f, 45.0f, 25.0f, 12.0f, 5.0f, 2.0f}) {
        Vec3f sun = Sun::directionFromAzimuthElevation(200, elevation);
        Cubemap sky = bakePreethamSky(sun, kSunIrradiance, SkySettings{});
        Vec3f e = skyIrradiance(sky);
        double redOverBlue = e.x / e.z;
        std::printf("sun elevation %4.1f: sky irradiance RGB %.4f %.4f %.4f, R/B %.4f\n", elevation, e.x, e.y, e.z,
                    redOverBlue);
        EXPECT_GT(redOverBlue, previous) << elevation;
        previous = redOverBlue;
    }
}

// Preetham's luminance alone, written out again from the paper for the quadrature below:
// Y_z · F(θ, γ) / F(0, θ_s) with the Perez coefficients for Y (appendix A.2).
double preethamLuminance(double cosTheta, double gamma, double thetaS, double T) {
    double A = 0.1787 * T - 1.4630, B = -0.3554 * T + 0.4275, C = -0.0227 * T + 5.3251, D = 0.1206 * T - 2.5771,
           E = -0.0670 * T + 0.3703;
    auto F = [&](double c, double g) {
        return (1 + A * std::exp(B / c)) * (1 + C * std::exp(D * g) + E * std::cos(g) * std::cos(g));
    };
    return preethamZenithLuminance(thetaS, T) * F(cosTheta, gamma) / F(1, thetaS);
}

TEST(Sky, SkyToSunRatioIsPreethamsAndGrowsWithHaze) {
    // What the sky adds on a horizontal surface, against the sun, must be what Preetham's
    // luminance gives against sunDirectNormalIlluminance: a (θ, φ) midpoint quadrature of the
    // paper's formula, independent of the cubemap, against the baked texels.
    //
    // For comparison with measurements: on clear days the diffuse fraction of global
    // horizontal irradiance is about 0.165 (Erbs, Klein & Duffie 1982, Solar Energy 28, for
    // clearness index k_T > 0.8) and the ESRA clear-sky model (Rigollier, Bauer & Wald 2000,
    // Solar Energy 68) gives 0.12 for Linke turbidity 3 and the sun at 60°. Preetham's sky is
    // brighter: its zenith luminance at T = 3 and 60° is 10.4 kcd/m² against 94.5 klx of sun,
    // so the fractions printed here run above that band; that is the model, not the scaling.
    const double elevation = 60, thetaS = (90 - elevation) * M_PI / 180;
    Vec3f sun = Sun::directionFromAzimuthElevation(180, float(elevation));
    double previous = 0;
    for (float turbidity : {2.0f, 3.0f, 4.0f, 6.0f}) {
        SkySettings settings;
        settings.turbidity = turbidity;
        Cubemap sky = bakePreethamSky(sun, kSunIrradiance, settings);
        double baked = luminance(skyIrradiance(sky)), direct = luminance(kSunIrradiance) * sun.z;

        constexpr int kThetaSteps = 300, kPhiSteps = 600;
        double integral = 0;
        for (int i = 0; i < kThetaSteps; ++i) {
            double theta = (i + 0.5) * (M_PI / 2) / kThetaSteps;
            for (int j = 0; j < kPhiSteps; ++j) {
                double phi = (j + 0.5) * 2 * M_PI / kPhiSteps;
                Vec3f d{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                        float(std::cos(theta))};
                double gamma = angleDegrees(d, sun) * M_PI / 180;
                double cosTheta = std::cos(theta);
                integral += preethamLuminance(cosTheta, gamma, thetaS, turbidity) * cosTheta * std::sin(theta);
            }
        }
        integral *= (M_PI / 2 / kThetaSteps) * (2 * M_PI / kPhiSteps);  // klx
        double expected = integral * luminance(kSunIrradiance) / sunDirectNormalIlluminance(elevation, turbidity);
        double fraction = baked / (baked + direct);
        std::printf(
            "T = %.0f, sun at 60 deg: sky %.4f (quadrature of Preetham %.4f, %.1f klx), sun %.4f on the "
            "horizontal; sky/sun %.4f, diffuse fraction %.4f\n",
            turbidity, baked, expected, integral, direct, baked / direct, fraction);
        EXPECT_NEAR(baked, expected, 0.001 * expected) << turbidity;  // midpoint rules on both sides
        EXPECT_GT(fraction, previous) << turbidity;
        previous = fraction;
    }
}

TEST(Sky, GroundReflectsTheSunAndSky) {
    Vec3f sun = Sun::directionFromAzimuthElevation(100, 30);
    Vec3f irradiance{3.2f, 3.0f, 2.7f};
    SkySettings settings;
    settings.groundAlbedo = 0.3f;
    Cubemap sky = bakePreethamSky(sun, irradiance, settings);
    Vec3f expected = (irradiance * sun.z + skyIrradiance(sky)) * (0.3f / kPi);
    int groundTexels = 0;
    forEachTexel(sky, [&](const Vec3f &L, const Vec3f &d, int, int) {
        if (d.z > 0) return;
        ++groundTexels;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(L[c], expected[c], 1e-5 * expected[c]);
    });
    EXPECT_EQ(groundTexels, 3 * 64 * 64);  // the down face and the lower halves of four sides
}

TEST(Sky, ScalesWithTheSunAndFadesBelowTheHorizon) {
    auto bake = [](float elevation, float irradiance) {
        return bakePreethamSky(Sun::directionFromAzimuthElevation(250, elevation), Vec3f{irradiance}, SkySettings{});
    };
    // Sky texels, compared by index: 1° is kMinSunElevationDegrees, −3° halfway to night.
    Cubemap reference = bake(1, 3), doubled = bake(1, 6), belowHorizonLimit = bake(0.5f, 3), dusk = bake(-3, 3),
            night = bake(-6.5f, 3);
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < reference.size(); ++y) {
            for (int x = 0; x < reference.size(); ++x) {
                if (reference.direction(face, float(x) + 0.5f, float(y) + 0.5f).z <= 0) continue;
                double L = luminance(reference.texel(face, x, y));
                EXPECT_NEAR(luminance(doubled.texel(face, x, y)), 2 * L, 1e-5 * L);
                EXPECT_NEAR(luminance(belowHorizonLimit.texel(face, x, y)), L, 1e-5 * L);
                EXPECT_NEAR(luminance(dusk.texel(face, x, y)), 0.5 * L, 1e-5 * L);
            }
        }
    }
    forEachTexel(night, [](const Vec3f &L, const Vec3f &, int, int) { EXPECT_EQ(L, Vec3f(0.0f)); });
}

}  // namespace
}  // namespace veduta
