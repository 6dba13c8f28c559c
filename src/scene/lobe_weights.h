// How a Phong material's colours share the light it reflects: the mirror takes its part first,
// k_d and k_s share the rest, scaled down together where their sum would reflect more than
// arrives. The path tracer's BSDF weighs its lobes so, and the preview draws what it weighs, so
// that the preview's albedo is the albedo pass's.
#pragma once

#include "core/vecmath.h"

namespace veduta {

struct LobeWeights {
    Vec3f diffuse, specular, mirror;
};

// From k_d, k_s and the mirror's reflectivity, each already times its map: negative values count
// as 0, the mirror is clamped to [0, 1].
LobeWeights lobeWeights(const Vec3f &diffuse, const Vec3f &specular, const Vec3f &mirror);

}  // namespace veduta
