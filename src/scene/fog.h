// Aerial perspective: height-dependent exponential fog between the camera and what it sees.
// The air's extinction falls off with height, σ(z) = density · exp(−(z − baseHeight) /
// scaleHeight); what it scatters towards the camera is the light of the sky and the sun
// scattered isotropically, so a white scene under a uniform sky keeps its radiance.
#pragma once

#include "core/vecmath.h"

namespace veduta {

struct Fog {
    float density = 0;         // extinction at baseHeight, 1/m; 0 = clear air
    float baseHeight = 0;      // m
    float scaleHeight = 1200;  // m: the extinction falls by e over this height
    Vec3f inscatter{0.0f};     // radiance of the fog itself, W/(m²·sr): buildRenderScene takes it from the sky

    bool enabled() const { return density > 0; }

    // The fraction of light that crosses `distance` metres from `origin` along the unit
    // `direction` (distance may be infinite).
    float transmittance(const Vec3f &origin, const Vec3f &direction, float distance) const;

    // What the camera sees of radiance L from `distance` away: attenuated, plus the fog's own.
    Vec3f apply(const Vec3f &L, const Vec3f &origin, const Vec3f &direction, float distance) const {
        float t = transmittance(origin, direction, distance);
        return L * t + inscatter * (1 - t);
    }
};

}  // namespace veduta
