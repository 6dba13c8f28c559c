// Warps from the unit square to directions, with their densities. Each routine has a χ² test
// in tests/render/sampling_test.cpp.
#pragma once

#include <cmath>

#include "core/vecmath.h"

namespace veduta {

// Cosine-weighted direction in the hemisphere around +z (Malley's method on a concentric disk).
Vec3f sampleCosineHemisphere(Vec2f u);
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0 ? cosTheta * kInvPi : 0.0f; }

// Uniform direction inside the cone of half-angle acos(cosThetaMax) around +z.
Vec3f sampleUniformCone(Vec2f u, float cosThetaMax);
inline float uniformConePdf(float cosThetaMax) { return 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)); }

// Uniform point on the unit disk (Shirley-Chiu concentric map).
Vec2f sampleConcentricDisk(Vec2f u);

}  // namespace veduta
