#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <random>

#include <tbb/task_arena.h>

#include "render/chi2.h"
#include "render/cubemap_distribution.h"
#include "scene/cubemap.h"

namespace veduta {
namespace {

// Significance 1 %, Šidák-corrected over the χ² tests of this file (pbrt-v4's choice).
constexpr int kChi2Tests = 3;
const double kAlpha = 1 - std::pow(1 - 0.01, 1.0 / kChi2Tests);

Cubemap baked(int size, const std::function<Vec3f(const Vec3f &)> &f) {
    Cubemap cube(size);
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) cube.texel(face, x, y) = f(cube.direction(face, x + 0.5f, y + 0.5f));
        }
    }
    return cube;
}

// A dim sky with a bright spot a few texels wide around `centre`.
Cubemap spotMap(const Vec3f &centre) {
    Vec3f axis = normalize(centre);
    return baked(32, [&](const Vec3f &d) {
        float angle = std::acos(std::clamp(dot(d, axis), -1.0f, 1.0f));
        return Vec3f(0.05f) + Vec3f{200, 150, 100} * std::exp(-angle * angle / (2 * 0.05f * 0.05f));
    });
}

Cubemap gradientMap() {
    return baked(32, [](const Vec3f &d) { return Vec3f{1 + d.z, 1 + 0.5f * d.x, 0.2f + d.y * d.y}; });
}

void expectSamplesMatchDensity(const Cubemap &cube, const char *name) {
    CubemapDistribution distribution(cube);
    // Densities jump at texel edges inside the test's cells: integrate each cell finely.
    test::Chi2Options options;
    options.subdivisions = 48;
    test::Chi2Result r = test::chi2Test([&](Vec2f u) { return distribution.sample(u).direction; },
                                        [&](const Vec3f &d) { return distribution.pdf(d); }, options);
    std::printf("[ chi2     ] %s: statistic %.1f, dof %d, p-value %.4f (alpha %.5f)\n", name, r.statistic,
                r.degreesOfFreedom, r.pValue, kAlpha);
    EXPECT_GT(r.pValue, kAlpha) << name << ": chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    EXPECT_EQ(r.outsideSupport, 0) << name;
}

TEST(CubemapDistribution, SamplesMatchDensityForASpotOnAnEdge) {
    expectSamplesMatchDensity(spotMap({1, 1, 0.3f}), "spot on the east-north edge");
}

TEST(CubemapDistribution, SamplesMatchDensityForASpotOnACorner) {
    expectSamplesMatchDensity(spotMap({-1, 1, 1}), "spot on the west-north-up corner");
}

TEST(CubemapDistribution, SamplesMatchDensityForAGradient) { expectSamplesMatchDensity(gradientMap(), "gradient"); }

TEST(CubemapDistribution, DensityIntegratesToOne) {
    // Stratified uniform directions, 1000 × 1000 strata equal in cos θ and φ.
    for (const Cubemap &cube : {spotMap({1, 1, 0.3f}), spotMap({-1, 1, 1}), gradientMap()}) {
        CubemapDistribution distribution(cube);
        std::mt19937 rng(13);
        std::uniform_real_distribution<double> jitter(0.0, 1.0);
        constexpr int kStrata = 1000;
        double sum = 0;
        for (int i = 0; i < kStrata; ++i) {
            for (int j = 0; j < kStrata; ++j) {
                double z = -1 + 2 * (i + jitter(rng)) / kStrata, phi = 2 * M_PI * (j + jitter(rng)) / kStrata;
                double r = std::sqrt(std::max(0.0, 1 - z * z));
                sum += distribution.pdf({float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)});
            }
        }
        double integral = sum / (double(kStrata) * kStrata) * 4 * M_PI;
        std::printf("[ integral ] %.5f\n", integral);
        EXPECT_NEAR(integral, 1, 0.01);
    }
}

TEST(CubemapDistribution, SampleDensityIsTheDensityOfItsDirection) {
    for (const Cubemap &cube : {spotMap({-1, 1, 1}), gradientMap()}) {
        CubemapDistribution distribution(cube);
        std::mt19937 rng(17);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        for (int i = 0; i < 100000; ++i) {
            Vec2f u{uniform(rng), uniform(rng)};
            EnvironmentSample s = distribution.sample(u);
            ASSERT_NEAR(length(s.direction), 1, 1e-6f);
            ASSERT_GT(s.pdf, 0);
            ASSERT_NEAR(distribution.pdf(s.direction), s.pdf, 1e-3f * s.pdf) << u.x << " " << u.y;
        }
    }
}

// MIS needs a density wherever the bilinear lookup has radiance, and none is wasted far away.
TEST(CubemapDistribution, DensityCoversWhereTheLookupShines) {
    Cubemap cube(16);
    cube.texel(kNorth, 15, 0) = Vec3f(10.0f);  // north's top-right corner, next to east and up
    CubemapDistribution distribution(cube);
    std::mt19937 rng(19);
    std::normal_distribution<float> normal;
    int lit = 0;
    for (int i = 0; i < 200000; ++i) {
        Vec3f d = normalize(Vec3f{1, 1, 1} + Vec3f{normal(rng), normal(rng), normal(rng)} * 0.15f);
        bool shines = maxComponent(cube.lookup(d)) > 0;
        lit += shines;
        if (shines) {
            ASSERT_GT(distribution.pdf(d), 0) << d.x << " " << d.y << " " << d.z;
        }
    }
    EXPECT_GT(lit, 1000);
    EXPECT_EQ(distribution.pdf({0, 0, -1}), 0);
    EXPECT_EQ(distribution.pdf({-1, 0, 0}), 0);
}

TEST(CubemapDistribution, BlackMapSamplesUniformly) {
    // Uniform by solid angle, up to the change of ln (1 + a² + b²)^(3/2) over half a texel
    // either way, 3·(|a| + |b|)/(1 + a² + b²) / 128 ≤ 3/(128·√2) < 1.7 %; uniform per texel
    // would be five times denser at the corners than at the centres.
    CubemapDistribution distribution{Cubemap(128)};
    float uniform = 1 / (4 * kPi);
    for (Vec3f d : {Vec3f{0.3f, -0.2f, 0.9f}, Vec3f{0, 0, -1}, Vec3f{1, 1, 1}, Vec3f{-1, 0.99f, 0.98f}}) {
        EXPECT_NEAR(distribution.pdf(normalize(d)), uniform, 0.017f * uniform) << d.x << " " << d.y << " " << d.z;
    }
    for (Vec2f u : {Vec2f{0.7f, 0.2f}, Vec2f{0.001f, 0.999f}, Vec2f{0.5f, 0.5f}}) {
        EXPECT_NEAR(distribution.sample(u).pdf, uniform, 0.017f * uniform) << u.x << " " << u.y;
    }
}

TEST(CubemapDistribution, BuildsFastAndTheSameOnAnyNumberOfThreads) {
    Cubemap cube = baked(512, [](const Vec3f &d) { return Vec3f{1 + d.z, 1 + d.x, std::exp(10 * d.y)}; });
    auto start = std::chrono::steady_clock::now();
    CubemapDistribution parallel(cube);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ build    ] 6x512x512 texels in %.3f s\n", seconds);
    std::optional<CubemapDistribution> serial;
    tbb::task_arena(1).execute([&] { serial.emplace(cube); });
    for (int i = 0; i < 1000; ++i) {
        Vec2f u{(float(i) + 0.5f) / 1000, float((i * 7919) % 1000) / 1000};
        EnvironmentSample a = parallel.sample(u), b = serial->sample(u);
        ASSERT_EQ(a.direction, b.direction);
        ASSERT_EQ(a.pdf, b.pdf);
    }
}

}  // namespace
}  // namespace veduta
