#include "render/phong.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace veduta {

namespace {

Vec3f mirrorAboutZ(const Vec3f &w) { return {-w.x, -w.y, w.z}; }

float clampExponent(float exponent) { return std::clamp(exponent, kMinPhongExponent, kMaxPhongExponent); }

// cos α between wi and the mirror image of wo; reflection is symmetric, so swapping the
// directions gives the same value (the lobe is reciprocal).
float cosToMirror(const Vec3f &wo, const Vec3f &wi) { return dot(mirrorAboutZ(wo), wi); }

// ∫₀^{2π} max(0, a + b cos φ) dφ for b ≥ 0: the part of a ring of directions around the mirror
// direction that lies above the horizon, weighted by cos θ.
double clippedRingIntegral(double a, double b) {
    if (a >= b) return 2 * M_PI * a;
    if (a <= -b) return 0;
    double phi0 = std::acos(-a / b);
    return 2 * (a * phi0 + b * std::sin(phi0));
}

// E(μ, n) by quadrature over the lobe's own warp: with t = cos^{n+1} α the density is uniform
// in t, so a midpoint rule in t places its nodes where the lobe is, for any n. The ring
// integral is done in closed form, which leaves a smooth 1D integrand.
double exactAlbedo(double mu, double n) {
    constexpr int kNodes = 512;
    double sinO = std::sqrt(std::max(0.0, 1 - mu * mu));
    double sum = 0;
    for (int k = 0; k < kNodes; ++k) {
        double cosAlpha = std::pow((k + 0.5) / kNodes, 1 / (n + 1));
        double sinAlpha = std::sqrt(std::max(0.0, 1 - cosAlpha * cosAlpha));
        sum += clippedRingIntegral(mu * cosAlpha, sinO * sinAlpha);
    }
    return (n + 2) / ((n + 1) * 2 * M_PI) * sum / kNodes;
}

// E over (x = √μ, y = log₁₀ n), bilinear. √μ spaces the nodes more densely towards grazing
// angles, where narrow lobes lose their energy. E_avg per exponent node is the exact integral
// of the piecewise-linear interpolant, so the compensation lobe reflects exactly 1 − E of the
// interpolated E: only E's own interpolation error (≤ 0.2 %) remains in a white furnace.
class AlbedoTable {
  public:
    static constexpr int kMu = 32, kExponents = 24;

    AlbedoTable() {
        for (int j = 0; j < kExponents; ++j) {
            double n = std::pow(10.0, maxLog10() * j / (kExponents - 1));
            for (int i = 0; i < kMu; ++i) {
                double x = double(i) / (kMu - 1);
                // The quadrature overshoots 1 by ~1e-5 at normal incidence; E > 1 would make the
                // compensation negative.
                albedo_[size_t(j * kMu + i)] = float(std::min(exactAlbedo(x * x, n), 1.0));
            }
            average_[size_t(j)] = float(averageOfInterpolant(j));
        }
    }

    float albedo(float mu, float exponent) const {
        Cell c = cellOf(mu, exponent);
        auto at = [&](int j, int i) { return albedo_[size_t(j * kMu + i)]; };
        float lower = (1 - c.fx) * at(c.j, c.i) + c.fx * at(c.j, c.i + 1);
        float upper = (1 - c.fx) * at(c.j + 1, c.i) + c.fx * at(c.j + 1, c.i + 1);
        return (1 - c.fy) * lower + c.fy * upper;
    }

    float average(float exponent) const {
        Cell c = cellOf(1, exponent);
        return (1 - c.fy) * average_[size_t(c.j)] + c.fy * average_[size_t(c.j + 1)];
    }

  private:
    struct Cell {
        int i, j;
        float fx, fy;
    };

    static double maxLog10() { return std::log10(double(kMaxPhongExponent)); }

    static Cell cellOf(float mu, float exponent) {
        float x = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kMu - 1);
        float y = std::log10(clampExponent(exponent)) / float(maxLog10()) * (kExponents - 1);
        int i = std::min(int(x), kMu - 2), j = std::min(int(y), kExponents - 2);
        return {i, j, x - float(i), y - float(j)};
    }

    // 2∫E μ dμ = 4∫E(x) x³ dx, each segment linear in x: E = a + b x.
    double averageOfInterpolant(int j) const {
        double sum = 0, h = 1.0 / (kMu - 1);
        for (int i = 0; i + 1 < kMu; ++i) {
            double x0 = i * h, x1 = (i + 1) * h;
            double e0 = albedo_[size_t(j * kMu + i)], e1 = albedo_[size_t(j * kMu + i + 1)];
            double b = (e1 - e0) / h, a = e0 - b * x0;
            sum += a * (std::pow(x1, 4) - std::pow(x0, 4)) + 0.8 * b * (std::pow(x1, 5) - std::pow(x0, 5));
        }
        return sum;
    }

    std::array<float, kMu * kExponents> albedo_{};
    std::array<float, kExponents> average_{};
};

const AlbedoTable &albedoTable() {
    static const AlbedoTable table;
    return table;
}

// cosⁿα, the shape the lobe and its density share; 0 below either horizon or past 90° from
// the mirror direction.
float phongShape(const Vec3f &wo, const Vec3f &wi, float n) {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    float cosAlpha = cosToMirror(wo, wi);
    if (cosAlpha <= 0) return 0;
    return std::pow(cosAlpha, n);
}

}  // namespace

float phongLobe(const Vec3f &wo, const Vec3f &wi, float exponent) {
    float n = clampExponent(exponent);
    return (n + 2) * (0.5f * kInvPi) * phongShape(wo, wi, n);
}

float phongPdf(const Vec3f &wo, const Vec3f &wi, float exponent) {
    float n = clampExponent(exponent);
    return (n + 1) * (0.5f * kInvPi) * phongShape(wo, wi, n);
}

std::optional<Vec3f> samplePhong(const Vec3f &wo, float exponent, Vec2f u) {
    if (wo.z <= 0) return std::nullopt;
    float n = clampExponent(exponent);
    // 1 − cos α straight from the logarithm: for n = 10⁴ cos α is within 10⁻⁴ of 1, where
    // u^{1/(n+1)} and then √(1 − cos²) would lose most of their digits in float.
    float oneMinusCos = -std::expm1(std::log(std::max(1 - u.x, 1e-30f)) / (n + 1));
    float cosAlpha = 1 - oneMinusCos;
    float sinAlpha = std::sqrt(std::max(0.0f, oneMinusCos * (2 - oneMinusCos)));
    float phi = 2 * kPi * u.y;
    Vec3f local{sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha};
    Vec3f wi = Frame::fromNormal(mirrorAboutZ(wo)).toWorld(local);
    if (wi.z <= 0) return std::nullopt;
    return wi;
}

float phongAlbedo(float cosTheta, float exponent) { return albedoTable().albedo(cosTheta, exponent); }

float phongCompensation(float cosThetaO, float cosThetaI, float exponent) {
    if (cosThetaO <= 0 || cosThetaI <= 0) return 0;
    const AlbedoTable &table = albedoTable();
    float missing = 1 - table.average(exponent);
    // A lobe that loses nothing needs no compensation (and would divide 0 by 0).
    if (missing <= 0) return 0;
    return (1 - table.albedo(cosThetaO, exponent)) * (1 - table.albedo(cosThetaI, exponent)) * kInvPi / missing;
}

}  // namespace veduta
