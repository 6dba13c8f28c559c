// The normalised (modified) Phong lobe of Lafortune and Willems, in a local frame whose z axis
// is the surface normal, and the energy it loses at grazing angles, given back by a
// Kulla–Conty style compensation lobe. Both directions point away from the surface.
//
//   lobe:          f = (n+2)/(2π) · cosⁿα,  α = angle between wi and the mirror image of wo
//   pdf:           (n+1)/(2π) · cosⁿα, sampled as cos α = u^{1/(n+1)} around the mirror direction
//   compensation:  f_ms = (1 − E(μo)) (1 − E(μi)) / (π (1 − E_avg))
//
// E(μ, n) is the lobe's directional albedo and E_avg = 2∫E(μ) μ dμ its hemispherical average;
// f_ms is symmetric and reflects exactly 1 − E(μo), so lobe plus compensation reflect all the
// light at every angle (Kulla and Conty, "Revisiting Physically Based Shading at Imageworks",
// 2017). Mitsuba 0.6 and Tungsten have the lobe without the compensation, and darken at
// grazing angles.
#pragma once

#include <optional>

#include "core/vecmath.h"

namespace veduta {

// Exponents are clamped to this range: below 1 the lobe is no gloss worth the name, above
// 10⁴ it is narrower than a pixel's footprint of any texture (use a mirror instead).
inline constexpr float kMinPhongExponent = 1.0f;
inline constexpr float kMaxPhongExponent = 1.0e4f;

// The lobe f (no colour, no cosine); 0 when either direction is below the surface.
float phongLobe(const Vec3f &wo, const Vec3f &wi, float exponent);
// The sampling density in solid angle; 0 when either direction is below the surface.
float phongPdf(const Vec3f &wo, const Vec3f &wi, float exponent);
// A direction around the mirror image of wo; none when it falls below the surface (the
// density then integrates to less than 1 over the hemisphere, which phongPdf accounts for).
std::optional<Vec3f> samplePhong(const Vec3f &wo, float exponent, Vec2f u);

// E(μ, n): the fraction of light arriving from a direction with cos θ = μ that the lobe
// reflects, interpolated from a table computed once by quadrature (32 √μ × 24 log n nodes,
// within 0.2 % of the exact integral).
float phongAlbedo(float cosTheta, float exponent);
// The compensation lobe f_ms / k_s for these two cosines (no cosine factor).
float phongCompensation(float cosThetaO, float cosThetaI, float exponent);

}  // namespace veduta
