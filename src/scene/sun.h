// The sun: a distant disc light given by where it stands and how much it lights a surface
// facing it.
#pragma once

#include <cmath>

#include "core/vecmath.h"

namespace veduta {

struct Sun {
    Vec3f direction = directionFromAzimuthElevation(135, 45);  // unit vector towards the sun
    Vec3f irradiance{3.0f};                                    // W/m² on a surface facing the sun, per RGB channel
    float angularDiameterDegrees = 0.53f;                      // 0 makes it a directional light

    bool enabled() const { return maxComponent(irradiance) > 0; }

    // Azimuth clockwise from north (+y) towards east (+x), elevation above the horizon,
    // both in degrees, as surveyors and sun-position tables give them.
    static Vec3f directionFromAzimuthElevation(float azimuthDegrees, float elevationDegrees) {
        float az = radians(azimuthDegrees), el = radians(elevationDegrees);
        return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
    }

    // 1 − cos of the disc's angular radius, as 2·sin²(radius/2): exact for small discs.
    float oneMinusCosRadius() const {
        float s = std::sin(radians(angularDiameterDegrees * 0.25f));
        return 2 * s * s;
    }
    // Whether a unit direction points into the disc. Compares sines via the cross product,
    // which stays exact for small angles where the cosine does not.
    bool discContains(const Vec3f &d) const {
        float omc = oneMinusCosRadius();
        Vec3f c = cross(d, direction);
        return dot(d, direction) > 0 && dot(c, c) <= omc * (2 - omc);
    }
    // Radiance of the disc that gives `irradiance` at normal incidence: E = L·π·sin²(θ/2).
    Vec3f discRadiance() const {
        float s = std::sin(radians(angularDiameterDegrees * 0.5f));
        return irradiance / (kPi * s * s);
    }
};

}  // namespace veduta
