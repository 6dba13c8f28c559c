// veduta's Phong materials in the terms of the formats it exports to.
#pragma once

#include <cmath>

#include "scene/material.h"

namespace veduta {

// The PBR roughness of a Phong exponent: Walter et al. 2007 match Phong's n to a microfacet
// width α = sqrt(2 / (n + 2)), and glTF's (and MTL's Pr) roughness is sqrt(α). Without a
// specular colour the surface is matte whatever n says; glass is smooth.
inline float roughnessFromPhong(const Material &m) {
    if (m.glass) return 0;
    if (maxComponent(m.specular) <= 0) return 1;
    return std::pow(2 / (m.shininess + 2), 0.25f);
}

// Reflectance of a dielectric at normal incidence: how much of a glass pane a viewer that knows
// only opacity should show.
inline float normalReflectance(float ior) {
    float r = (ior - 1) / (ior + 1);
    return r * r;
}

}  // namespace veduta
