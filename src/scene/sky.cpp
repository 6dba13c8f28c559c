#include "scene/sky.h"

#include <algorithm>
#include <cmath>

namespace veduta {

namespace {

constexpr double kDegrees = 180.0 / M_PI;
constexpr double kRadians = M_PI / 180.0;

// The Y row of the inverse of the XYZ → Rec.709 matrix below, so that a sky colour's
// luminance is the model's Y to rounding.
double rec709Luminance(double r, double g, double b) { return 0.2126729 * r + 0.7151522 * g + 0.0721750 * b; }

// The Perez et al. 1993 sky distribution with its five coefficients.
struct Perez {
    double A, B, C, D, E;

    double operator()(double cosTheta, double gamma) const {
        double cosGamma = std::cos(gamma);
        return (1 + A * std::exp(B / cosTheta)) * (1 + C * std::exp(D * gamma) + E * cosGamma * cosGamma);
    }
};

// Preetham et al. 1999, appendix A.2: the coefficients as linear functions of turbidity.
Perez luminanceDistribution(double T) {
    return {0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771, -0.0670 * T + 0.3703};
}
Perez xDistribution(double T) {
    return {-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989,
            -0.0033 * T + 0.0452};
}
Perez yDistribution(double T) {
    return {-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537,
            -0.0109 * T + 0.0529};
}

// Preetham et al. 1999, appendix A.2: zenith chromaticity as [T² T 1] · M · [θ³ θ² θ 1]ᵀ.
using ChromaticityMatrix = double[3][4];
constexpr ChromaticityMatrix kZenithX = {
    {0.00166, -0.00375, 0.00209, 0}, {-0.02903, 0.06377, -0.03202, 0.00394}, {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr ChromaticityMatrix kZenithY = {
    {0.00275, -0.00610, 0.00317, 0}, {-0.04214, 0.08970, -0.04153, 0.00516}, {0.15346, -0.26756, 0.06670, 0.26688}};

double zenithChromaticity(const ChromaticityMatrix &m, double thetaS, double T) {
    double theta[4] = {thetaS * thetaS * thetaS, thetaS * thetaS, thetaS, 1};
    double turbidity[3] = {T * T, T, 1};
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) sum += turbidity[i] * m[i][j] * theta[j];
    return sum;
}

// Kasten & Young 1989, "Revised optical air mass tables and approximation formula".
double relativeAirMass(double elevationDegrees) {
    return 1 / (std::sin(elevationDegrees * kRadians) + 0.50572 * std::pow(elevationDegrees + 6.07995, -1.6364));
}

// The model for one sun position: radiance in kcd/m², as linear Rec.709 RGB.
class PreethamModel {
  public:
    PreethamModel(const Vec3f &sun, double turbidity) :
        sun_(sun), Y_(luminanceDistribution(turbidity)), x_(xDistribution(turbidity)), y_(yDistribution(turbidity)) {
        double thetaS = std::acos(std::clamp(double(sun.z), -1.0, 1.0));
        // Dividing by F(0, θ_s) makes each distribution equal its zenith value at the zenith.
        zenithLuminance_ = preethamZenithLuminance(thetaS, turbidity) / Y_(1, thetaS);
        zenithChromaX_ = zenithChromaticity(kZenithX, thetaS, turbidity) / x_(1, thetaS);
        zenithChromaY_ = zenithChromaticity(kZenithY, thetaS, turbidity) / y_(1, thetaS);
    }

    // For a unit direction above the horizon.
    Vec3f radiance(const Vec3f &d) const {
        double cosTheta = d.z;
        double gamma = std::acos(std::clamp(double(dot(d, sun_)), -1.0, 1.0));
        double Y = zenithLuminance_ * Y_(cosTheta, gamma);
        double x = zenithChromaX_ * x_(cosTheta, gamma), y = zenithChromaY_ * y_(cosTheta, gamma);
        double X = x / y * Y, Z = (1 - x - y) / y * Y;
        // CIE XYZ to linear Rec.709 (sRGB primaries, D65 white).
        double r = 3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z;
        double g = -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z;
        double b = 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z;
        return {float(std::max(r, 0.0)), float(std::max(g, 0.0)), float(std::max(b, 0.0))};
    }

  private:
    Vec3f sun_;
    Perez Y_, x_, y_;
    double zenithLuminance_, zenithChromaX_, zenithChromaY_;
};

// The sun direction with its elevation raised to at least `elevationDegrees`, same azimuth.
Vec3f raisedSun(const Vec3f &sun, double elevationDegrees) {
    if (std::asin(std::clamp(double(sun.z), -1.0, 1.0)) * kDegrees >= elevationDegrees) return sun;
    double horizontal = std::hypot(double(sun.x), double(sun.y));
    // A sun straight below has no azimuth; any will do, it is faded out.
    Vec3f towards = horizontal > 1e-9 ? Vec3f{float(sun.x / horizontal), float(sun.y / horizontal), 0} : Vec3f{0, 1, 0};
    float c = float(std::cos(elevationDegrees * kRadians)), s = float(std::sin(elevationDegrees * kRadians));
    return {towards.x * c, towards.y * c, s};
}

}  // namespace

double preethamZenithLuminance(double thetaS, double T) {
    double chi = (4.0 / 9.0 - T / 120.0) * (M_PI - 2 * thetaS);
    return (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
}

double sunDirectNormalIlluminance(double elevationDegrees, double T) {
    constexpr double kLuminousSolarConstantKlx = 133.8;
    double m = relativeAirMass(elevationDegrees);
    return kLuminousSolarConstantKlx * std::exp(-T * m / (9.9 + 0.043 * m));
}

Cubemap bakePreethamSky(const Vec3f &sunDirection, const Vec3f &sunIrradiance, const SkySettings &settings) {
    double elevation = std::asin(std::clamp(double(sunDirection.z), -1.0, 1.0)) * kDegrees;
    double modelElevation = std::max(elevation, kMinSunElevationDegrees);
    double fade = std::clamp(1 - elevation / kNightSunElevationDegrees, 0.0, 1.0);
    double scale = fade * rec709Luminance(sunIrradiance.x, sunIrradiance.y, sunIrradiance.z) /
        sunDirectNormalIlluminance(modelElevation, settings.turbidity);
    PreethamModel model(raisedSun(sunDirection, modelElevation), settings.turbidity);

    Cubemap sky(settings.faceSize);
    double skyIrradiance[3] = {0, 0, 0};
    auto forEachTexel = [&](auto &&f) {
        for (int face = 0; face < kCubeFaceCount; ++face)
            for (int y = 0; y < sky.size(); ++y)
                for (int x = 0; x < sky.size(); ++x)
                    f(face, x, y, sky.direction(face, float(x) + 0.5f, float(y) + 0.5f));
    };
    forEachTexel([&](int face, int x, int y, const Vec3f &d) {
        if (d.z <= 0) return;
        Vec3f L = model.radiance(d) * float(scale);
        sky.texel(face, x, y) = L;
        double weight = double(d.z) * sky.texelSolidAngle(x, y);
        for (int c = 0; c < 3; ++c) skyIrradiance[c] += L[c] * weight;
    });

    Vec3f groundIrradiance = sunIrradiance * std::max(sunDirection.z, 0.0f) +
        Vec3f{float(skyIrradiance[0]), float(skyIrradiance[1]), float(skyIrradiance[2])};
    Vec3f ground = groundIrradiance * (settings.groundAlbedo * kInvPi);
    forEachTexel([&](int face, int x, int y, const Vec3f &d) {
        if (d.z <= 0) sky.texel(face, x, y) = ground;
    });
    return sky;
}

}  // namespace veduta
