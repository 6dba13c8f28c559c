#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "render/bsdf.h"
#include "render/chi2.h"
#include "render/phong.h"
#include "scene/shading_normal.h"

namespace veduta {
namespace {

// χ² tests of the Bsdf's sampling against its pdf: 4 exponents × 4 (k_d, k_s) × 3 angles, and
// the normal-mapped cases. Significance 1 %, Šidák-corrected over all of them.
constexpr float kExponents[] = {1, 10, 100, 1000};
constexpr float kIncidenceDegrees[] = {0, 45, 80};
struct Weights {
    float diffuse, specular;
};
constexpr Weights kWeights[] = {{0.5f, 0.5f}, {0.9f, 0.1f}, {0.0f, 1.0f}, {0.2f, 0.3f}};
constexpr int kTiltedChi2Tests = 4;
constexpr int kChi2Tests = 4 * 4 * 3 + kTiltedChi2Tests;
const double kAlpha = 1 - std::pow(1 - 0.01, 1.0 / kChi2Tests);

const Vec3f kUp{0, 0, 1};

Vec3f fromSpherical(float thetaDegrees, float phiDegrees) {
    float theta = radians(thetaDegrees), phi = radians(phiDegrees);
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Vec3f reflect(const Vec3f &w, const Vec3f &n) { return n * (2 * dot(n, w)) - w; }

BsdfInputs phong(float kd, float ks, float exponent) {
    BsdfInputs in;
    in.diffuse = Vec3f(kd);
    in.specular = Vec3f(ks);
    in.exponent = exponent;
    return in;
}

// The χ² test of `bsdf` at wo, with the grid's pole on the mirror direction and bins fine
// enough that the Phong lobe spans at least three of them. A declined sample, or a delta one,
// counts in the χ² test's "declined" cell.
test::Chi2Result chi2OfBsdf(const Bsdf &bsdf, const Vec3f &wo, const Vec3f &ns, float exponent) {
    // A new seed for every test, so that their p-values are independent.
    static uint32_t seed = 100;
    ++seed;
    std::mt19937 lobeRng(seed + 1000);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    auto sample = [&](Vec2f u) {
        std::optional<BsdfSample> s = bsdf.sample(wo, uniform(lobeRng), u);
        return s && !s->delta ? s->wi : Vec3f(0.0f);
    };
    auto pdf = [&](const Vec3f &wi) { return bsdf.pdf(wo, wi); };
    test::Chi2Options options;
    options.declines = true;
    options.equalAngleBins = true;
    options.frame = Frame::fromNormal(reflect(wo, ns));
    float lobeWidth = std::sqrt(2 / exponent);  // cosⁿα = 1/e there
    options.thetaBins = std::max(90, int(std::ceil(3 * kPi / lobeWidth)));
    options.phiBins = 48;
    options.seed = seed;
    return test::chi2Test(sample, pdf, options);
}

void phongChi2Tests(float exponent) {
    for (Weights w : kWeights) {
        for (float thetaO : kIncidenceDegrees) {
            Bsdf bsdf(phong(w.diffuse, w.specular, exponent), kUp, kUp);
            Vec3f wo = fromSpherical(thetaO, 30);
            test::Chi2Result r = chi2OfBsdf(bsdf, wo, kUp, exponent);
            std::printf("chi2 n=%-5g kd=%.1f ks=%.1f theta_o=%2g: p=%.4f (chi2 %.1f, dof %d)\n", exponent, w.diffuse,
                        w.specular, thetaO, r.pValue, r.statistic, r.degreesOfFreedom);
            EXPECT_GT(r.pValue, kAlpha) << "n " << exponent << " kd " << w.diffuse << " theta_o " << thetaO;
            EXPECT_LT(r.outsideSupport, 1e-5);
        }
    }
}

TEST(BsdfChi2, PhongExponent1) { phongChi2Tests(1); }
TEST(BsdfChi2, PhongExponent10) { phongChi2Tests(10); }
TEST(BsdfChi2, PhongExponent100) { phongChi2Tests(100); }
TEST(BsdfChi2, PhongExponent1000) { phongChi2Tests(1000); }

// With a tilted shading normal, samples below the geometric surface are declined and the
// pdf must leave them out; with a mirror lobe, the delta samples are missing mass too.
TEST(BsdfChi2, NormalMappedAndWithMirror) {
    struct Case {
        float tiltDegrees, thetaO, exponent;
        Vec3f mirror;
    };
    const Case cases[kTiltedChi2Tests] = {
        {30, 60, 10, Vec3f(0.0f)}, {50, 80, 100, Vec3f(0.0f)}, {20, 45, 1000, Vec3f(0.0f)}, {0, 30, 30, Vec3f(0.3f)}};
    for (const Case &c : cases) {
        Vec3f ns = fromSpherical(c.tiltDegrees, 0);
        Vec3f wo = fromSpherical(c.thetaO, 180);  // tilted away from the normal: the hard side
        ns = ensureValidReflection(kUp, wo, ns);
        BsdfInputs in = phong(0.4f, 0.4f, c.exponent);
        in.mirror = c.mirror;
        Bsdf bsdf(in, ns, kUp);
        test::Chi2Result r = chi2OfBsdf(bsdf, wo, ns, c.exponent);
        std::printf("chi2 tilt=%2g theta_o=%2g n=%-5g mirror=%.1f: p=%.4f (chi2 %.1f, dof %d)\n", c.tiltDegrees,
                    c.thetaO, c.exponent, c.mirror.x, r.pValue, r.statistic, r.degreesOfFreedom);
        EXPECT_GT(r.pValue, kAlpha) << "tilt " << c.tiltDegrees;
        EXPECT_LT(r.outsideSupport, 1e-5);
    }
}

// The grid resolves the narrowest lobe: a density 10 % too narrow is rejected.
TEST(BsdfChi2, RejectsAWrongExponent) {
    Bsdf bsdf(phong(0, 1, 1000), kUp, kUp), narrower(phong(0, 1, 1100), kUp, kUp);
    Vec3f wo = fromSpherical(30, 0);
    std::mt19937 lobeRng(11);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    test::Chi2Options options;
    options.declines = true;
    options.equalAngleBins = true;
    options.frame = Frame::fromNormal(reflect(wo, kUp));
    options.thetaBins = 300;
    options.phiBins = 48;
    test::Chi2Result r = test::chi2Test(
        [&](Vec2f u) {
            std::optional<BsdfSample> s = bsdf.sample(wo, uniform(lobeRng), u);
            return s ? s->wi : Vec3f(0.0f);
        },
        [&](const Vec3f &wi) { return narrower.pdf(wo, wi); }, options);
    std::printf("chi2 against n=1100 for n=1000 samples: p=%.3g\n", r.pValue);
    EXPECT_LT(r.pValue, 1e-6);
}

// ∫ f |cos| dω by the Bsdf's own samples (weights), delta lobes included.
Vec3f albedoBySampling(const Bsdf &bsdf, const Vec3f &wo, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    Vec3f sum(0.0f);
    for (int k = 0; k < count; ++k) {
        float uLobe = uniform(rng);
        Vec2f u{uniform(rng), uniform(rng)};
        if (std::optional<BsdfSample> s = bsdf.sample(wo, uLobe, u)) sum += s->weight;
    }
    return sum / float(count);
}

TEST(Bsdf, ReflectsAtMostWhatArrives) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    float worst = 0;
    for (int k = 0; k < 100; ++k) {
        BsdfInputs in;
        // Unclamped inputs: the constructor must bring k_d + k_s + mirror down to 1.
        in.diffuse = {uniform(rng), uniform(rng), uniform(rng)};
        in.specular = Vec3f(uniform(rng));
        in.mirror = Vec3f(k % 3 == 0 ? 0.5f * uniform(rng) : 0.0f);
        in.exponent = std::pow(10.0f, 4 * uniform(rng));
        Vec3f ns = k % 2 ? kUp : fromSpherical(40 * uniform(rng), 360 * uniform(rng));
        Vec3f wo = fromSpherical(89.5f * std::sqrt(uniform(rng)), 360 * uniform(rng));
        ns = ensureValidReflection(kUp, wo, ns);
        Vec3f albedo = albedoBySampling(Bsdf(in, ns, kUp), wo, 1 << 15, uint32_t(k));
        worst = std::max(worst, maxComponent(albedo));
        EXPECT_LE(maxComponent(albedo), 1.01f) << "case " << k;
    }
    std::printf("energy: largest albedo over 100 random materials and directions %.4f\n", worst);
}

// White furnace at the BSDF: with k_d + k_s = 1 the lobes reflect all the light at every angle.
// Without the compensation the Phong lobe alone reflects E(μo), far below 1 near grazing.
TEST(Bsdf, WhiteFurnaceWithPhong) {
    for (float exponent : kExponents) {
        for (Weights w : {Weights{0, 1}, Weights{0.5f, 0.5f}}) {
            float worst = 0;
            for (float thetaO : {0.0f, 15.0f, 30.0f, 45.0f, 60.0f, 75.0f, 85.0f, 89.0f}) {
                Vec3f wo = fromSpherical(thetaO, 20);
                Vec3f albedo = albedoBySampling(Bsdf(phong(w.diffuse, w.specular, exponent), kUp, kUp), wo, 1 << 16, 5);
                worst = std::max(worst, std::abs(albedo.x - 1));
                EXPECT_NEAR(albedo.x, 1.0f, 0.01f) << "n " << exponent << " kd " << w.diffuse << " theta_o " << thetaO;
            }
            std::printf("furnace n=%-5g kd=%.1f ks=%.1f: largest |albedo - 1| %.4f; Phong alone at 89 deg: %.3f\n",
                        exponent, w.diffuse, w.specular, worst, phongAlbedo(std::cos(radians(89)), exponent));
        }
    }
}

// A normal-mapped diffuse plane (k_d = 1) under a white sky: 1 within 1 % for shading normals
// tilted up to 60° and every view, grazing ones included (no black edges, no darkening).
TEST(Bsdf, WhiteFurnaceWithNormalMap) {
    for (float tilt : {0.0f, 15.0f, 30.0f, 45.0f, 60.0f}) {
        float worst = 0;
        for (float thetaO : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
            for (float phiO : {0.0f, 90.0f, 180.0f}) {
                Vec3f wo = fromSpherical(thetaO, phiO);
                Vec3f ns = ensureValidReflection(kUp, wo, fromSpherical(tilt, 0));
                Vec3f albedo = albedoBySampling(Bsdf(phong(1, 0, 1), ns, kUp), wo, 1 << 16, 9);
                worst = std::max(worst, std::abs(albedo.x - 1));
                EXPECT_NEAR(albedo.x, 1.0f, 0.01f) << "tilt " << tilt << " theta_o " << thetaO << " phi_o " << phiO;
            }
        }
        std::printf("furnace normal map tilt=%2g: largest |albedo - 1| %.4f\n", tilt, worst);
    }
}

// The table against a Monte Carlo integral of the lobe itself.
TEST(Phong, AlbedoTableMatchesTheLobe) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (float exponent : {1.0f, 7.0f, 100.0f, 3000.0f}) {
        for (float thetaO : {0.0f, 40.0f, 70.0f, 85.0f, 89.0f}) {
            Vec3f wo = fromSpherical(thetaO, 0);
            // Stratified: one jittered sample in each cell of a 512 × 256 grid.
            double sum = 0;
            constexpr int kRows = 512, kColumns = 256;
            for (int i = 0; i < kRows; ++i) {
                for (int j = 0; j < kColumns; ++j) {
                    Vec2f u{(float(i) + uniform(rng)) / kRows, (float(j) + uniform(rng)) / kColumns};
                    std::optional<Vec3f> wi = samplePhong(wo, exponent, u);
                    if (wi) sum += phongLobe(wo, *wi, exponent) * wi->z / phongPdf(wo, *wi, exponent);
                }
            }
            double albedo = sum / (kRows * kColumns);
            EXPECT_NEAR(phongAlbedo(wo.z, exponent), albedo, 0.003) << "n " << exponent << " theta_o " << thetaO;
        }
    }
}

TEST(Bsdf, IsReciprocal) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int k = 0; k < 2000; ++k) {
        // A fixed shading normal, plain, or tilted for the glossy lobes alone. The diffuse lobe
        // folded under a tilted normal is not reciprocal (see Bsdf::foldedCosine), and in
        // rendering ensureValidReflection makes the normal depend on wo, which breaks
        // reciprocity where it turns the normal (grazing views of strongly tilted normals).
        bool tilted = k % 2 == 0;
        Vec3f ns = tilted ? fromSpherical(45 * uniform(rng), 360 * uniform(rng)) : kUp;
        Bsdf bsdf(phong(tilted ? 0.0f : 0.3f, 0.7f, std::pow(10.0f, 3 * uniform(rng))), ns, kUp);
        Vec3f a = fromSpherical(89 * uniform(rng), 360 * uniform(rng));
        Vec3f b = uniform(rng) < 0.5f ? reflect(a, ns) : fromSpherical(89 * uniform(rng), 360 * uniform(rng));
        Vec3f fab = bsdf.eval(a, b) / std::abs(dot(b, ns)), fba = bsdf.eval(b, a) / std::abs(dot(a, ns));
        EXPECT_NEAR(fab.x, fba.x, 1e-4f * std::max(1.0f, fab.x)) << "case " << k;
    }
}

TEST(Bsdf, SampleAgreesWithPdfAndEval) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    int checked = 0;
    for (int k = 0; k < 5000; ++k) {
        BsdfInputs in = phong(uniform(rng), uniform(rng), std::pow(10.0f, 4 * uniform(rng)));
        in.mirror = Vec3f(k % 4 == 0 ? 0.3f : 0.0f);
        Vec3f wo = fromSpherical(89 * uniform(rng), 360 * uniform(rng));
        Vec3f ns = ensureValidReflection(kUp, wo, fromSpherical(30 * uniform(rng), 360 * uniform(rng)));
        Bsdf bsdf(in, ns, kUp);
        std::optional<BsdfSample> s = bsdf.sample(wo, uniform(rng), {uniform(rng), uniform(rng)});
        if (!s || s->delta) continue;
        ++checked;
        EXPECT_NEAR(bsdf.pdf(wo, s->wi), s->pdf, 1e-5f * s->pdf);
        Vec3f expected = bsdf.eval(wo, s->wi) / s->pdf;
        EXPECT_NEAR(s->weight.x, expected.x, 1e-5f * expected.x);
        EXPECT_GT(dot(s->wi, kUp), 0);
    }
    EXPECT_GT(checked, 3000);
}

TEST(Bsdf, MirrorIsADeltaLobeTakingItsShareFirst) {
    BsdfInputs in = phong(0.8f, 0.2f, 50);
    in.mirror = Vec3f(0.25f);
    Bsdf bsdf(in, kUp, kUp);
    Vec3f wo = fromSpherical(30, 0);
    std::optional<BsdfSample> s = bsdf.sample(wo, 0.9999f, {0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_NEAR(dot(s->wi, reflect(wo, kUp)), 1.0f, 1e-6f);
    // What the other lobes reflect shrinks to 1 − mirror, so the total stays 1.
    EXPECT_NEAR(albedoBySampling(bsdf, wo, 1 << 16, 2).x, 1.0f, 0.01f);
    EXPECT_TRUE(bsdf.hasNonDeltaLobe());
    BsdfInputs pureMirror = phong(0, 0, 1);
    pureMirror.mirror = Vec3f(1.0f);
    EXPECT_FALSE(Bsdf(pureMirror, kUp, kUp).hasNonDeltaLobe());
}

TEST(Bsdf, DirectionsBelowTheGeometricSurfaceGetNothing) {
    // A shading normal tilted 40° lets its lobes reach below the geometric surface.
    Vec3f ns = fromSpherical(40, 0);
    Bsdf bsdf(phong(0.5f, 0.5f, 10), ns, kUp);
    Vec3f wo = fromSpherical(30, 0);
    Vec3f below = normalize(Vec3f{1, 0, -0.2f});  // above the shading horizon, below the geometric one
    ASSERT_GT(dot(below, ns), 0);
    EXPECT_EQ(bsdf.eval(wo, below), Vec3f(0.0f));
    EXPECT_EQ(bsdf.pdf(wo, below), 0.0f);
}

TEST(ThinGlass, ReflectsAndTransmitsEverything) {
    constexpr float kIor = 1.5f;
    float r = (kIor - 1) / (kIor + 1);
    r *= r;
    EXPECT_NEAR(fresnelDielectric(1, kIor), r, 1e-6f);
    BsdfInputs in;
    in.thinGlass = true;
    in.ior = kIor;
    for (float thetaO : {0.0f, 30.0f, 60.0f, 85.0f}) {
        Vec3f wo = fromSpherical(thetaO, 0);
        Bsdf glass(in, kUp, kUp);
        EXPECT_FALSE(glass.hasNonDeltaLobe());
        std::optional<BsdfSample> reflected = glass.sample(wo, 0, {0.5f, 0.5f});
        std::optional<BsdfSample> transmitted = glass.sample(wo, 0.9999f, {0.5f, 0.5f});
        ASSERT_TRUE(reflected && transmitted);
        EXPECT_TRUE(reflected->delta && transmitted->delta);
        EXPECT_NEAR(dot(reflected->wi, reflect(wo, kUp)), 1.0f, 1e-6f);
        EXPECT_EQ(transmitted->wi, -wo);
        float transmittance = thinGlassTransmittance(wo.z, kIor, Vec3f(1.0f)).x;
        EXPECT_NEAR(reflected->pdf + transmittance, 1.0f, 1e-6f);
        EXPECT_NEAR(transmitted->pdf, transmittance, 1e-6f);
        EXPECT_EQ(reflected->weight, Vec3f(1.0f));
        if (thetaO == 0) {
            EXPECT_NEAR(reflected->pdf, 2 * r / (1 + r), 1e-6f);
        }
    }
    // A tint colours what passes, not what is reflected.
    EXPECT_NEAR(thinGlassTransmittance(1, kIor, {0.5f, 1, 1}).x, 0.5f * (1 - 2 * r / (1 + r)), 1e-6f);
}

TEST(ShadingNormal, EnsureValidReflectionLiftsTheMirrorDirection) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    int corrected = 0;
    for (int k = 0; k < 100000; ++k) {
        Frame frame =
            Frame::fromNormal(normalize(Vec3f{uniform(rng) - 0.5f, uniform(rng) - 0.5f, uniform(rng) - 0.5f}));
        Vec3f ng = frame.n;
        Vec3f wo = frame.toWorld(fromSpherical(89.9f * uniform(rng), 360 * uniform(rng)));
        Vec3f n = frame.toWorld(fromSpherical(85 * uniform(rng), 360 * uniform(rng)));
        Vec3f fixed = ensureValidReflection(ng, wo, n);
        float threshold = std::min(0.9f * dot(ng, wo), 0.01f);
        EXPECT_NEAR(length(fixed), 1.0f, 1e-5f);
        EXPECT_GT(dot(reflect(wo, fixed), ng), 0) << "case " << k;
        if (dot(reflect(wo, n), ng) >= threshold) {
            EXPECT_EQ(fixed, n);
        } else {
            ++corrected;
            // Turned in the plane of ng and n, and just far enough: the reflection lies at t.
            EXPECT_NEAR(dot(cross(ng, n), fixed), 0.0f, 1e-4f);
            EXPECT_NEAR(dot(reflect(wo, fixed), ng), threshold, 1e-3f) << "case " << k;
        }
    }
    std::printf("ensureValidReflection corrected %d of 100000 random normals\n", corrected);
    EXPECT_GT(corrected, 1000);
}

TEST(ShadingNormal, NormalFromMapDecodesTangentSpace) {
    Vec3f n = kUp, tangent = normalize(Vec3f{1, 0, 0.3f});  // not orthogonal to n yet
    auto near = [](const Vec3f &a, const Vec3f &b) { return length(a - b) < 1e-5f; };
    EXPECT_TRUE(near(normalFromMap({0.5f, 0.5f, 1}, n, tangent, 1, 1), n));
    EXPECT_TRUE(near(normalFromMap({1, 0.5f, 0.5f}, n, tangent, 1, 1), {1, 0, 0}));
    EXPECT_TRUE(near(normalFromMap({0.5f, 1, 0.5f}, n, tangent, 1, 1), {0, 1, 0}));    // green = +bitangent
    EXPECT_TRUE(near(normalFromMap({0.5f, 1, 0.5f}, n, tangent, -1, 1), {0, -1, 0}));  // mirrored uvs
    Vec3f tilted{0.75f, 0.5f, 0.5f + 0.5f * std::sqrt(0.75f)};                         // 30° towards the tangent
    EXPECT_TRUE(near(normalFromMap(tilted, n, tangent, 1, 0), n));
    EXPECT_TRUE(near(normalFromMap(tilted, n, tangent, 1, 1), fromSpherical(30, 0)));
    // Strength blends as Cycles does: half way between n and the mapped normal.
    EXPECT_TRUE(near(normalFromMap(tilted, n, tangent, 1, 0.5f), normalize(n + fromSpherical(30, 0))));
}

}  // namespace
}  // namespace veduta
