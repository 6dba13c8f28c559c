// An analytic clear sky, Preetham, Shirley & Smits 1999, "A Practical Analytic Model for
// Daylight" (SIGGRAPH 99), baked into a cubemap for the environment.
//
// The model: luminance Y and chromaticity x, y each follow the Perez distribution
//   F(θ, γ) = (1 + A·e^(B / cos θ)) · (1 + C·e^(D·γ) + E·cos² γ)
// (θ the view direction's zenith angle, γ its angle to the sun) with the paper's turbidity
// coefficients, scaled to the zenith values: Y = Y_z · F(θ, γ) / F(0, θ_s), where Y_z in
// kcd/m², x_z and y_z are the paper's zenith formulas. xyY → XYZ → linear Rec.709 RGB;
// chromaticities outside the Rec.709 gamut lose their negative channels. The sun's disc is
// not in the sky: the scene's Sun light carries it.
//
// Brightness against the sun: the sky must not be brighter or darker against the scene's sun
// than the model says. The scene gives the sun's irradiance at normal incidence in its own
// units; its Rec.709 luminance stands for the sun's direct normal illuminance at the same
// elevation and turbidity,
//   E_sun = 133.8 klx · exp(−T · m / (9.9 + 0.043·m)),
// the CIE luminous turbidity relation E = E_0·exp(−a_v·m·T_v) (CIE ILV 17-29-108) with
// Kittler's luminous Rayleigh extinction a_v = 1/(9.9 + 0.043·m), the luminous solar
// constant E_0 = 133.8 klx (Darula, Kittler & Gueymard 2005, Solar Energy 79) and Kasten &
// Young's 1989 air mass m. Preetham's T and the luminous turbidity are both the ratio of
// the hazy to the clean (Rayleigh) atmosphere's optical thickness, taken as equal here. So a
// sky luminance L (kcd/m²) becomes L · luminance(sunIrradiance) / E_sun (klx) in scene units.
// A sun of zero irradiance therefore gives a black sky. (E_sun agrees within a few percent
// with Preetham's own spectral sun transmittance at 550 nm.) Preetham's skies are brighter
// than measured clear days: with the sun at 60° the sky gives 28% of the horizontal
// illuminance at T = 3 and 21% at T = 2, where clear-day measurements give 12–17%.
//
// Below the horizon the cubemap holds a uniform grey ground, radiance
// groundAlbedo · (sun + sky irradiance on a horizontal surface) / π: what a Lambertian ground
// lit by this sun and sky reflects, so that light escaping downwards stays consistent.
//
// Each texel takes the value at its centre direction (no sub-texel averaging: the model is
// smooth at the default 64 texels per face, 1.4° each, and its circumsolar term is a few
// tens of degrees wide).
//
// Preetham's model is fitted for the sun above the horizon. For a sun below kMinSunElevation
// the sky is the model's with the sun raised to kMinSunElevation, measured against the sun's
// illuminance there, and faded linearly to black at kNightSunElevation (−6°, the end of
// civil twilight).
#pragma once

#include "core/vecmath.h"
#include "scene/cubemap.h"

namespace veduta {

struct SkySettings {
    float turbidity = 3;  // Preetham's T: 2 very clear, 3 clear, 6 hazy; the fit covers 2 to 10
    float groundAlbedo = 0.2f;
    int faceSize = 64;
};

inline constexpr double kMinSunElevationDegrees = 1;
inline constexpr double kNightSunElevationDegrees = -6;

// Preetham's zenith luminance Y_z, in kcd/m², for the sun at zenith angle θ_s (radians).
double preethamZenithLuminance(double sunZenithRadians, double turbidity);

// The sun's direct normal illuminance in klx at an elevation and turbidity, as above.
double sunDirectNormalIlluminance(double sunElevationDegrees, double turbidity);

// `sunDirection` is the unit vector towards the sun (ENU), `sunIrradiance` the sun's
// irradiance at normal incidence in scene units (Sun::irradiance).
Cubemap bakePreethamSky(const Vec3f &sunDirection, const Vec3f &sunIrradiance, const SkySettings &settings);

}  // namespace veduta
