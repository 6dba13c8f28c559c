// Warps from the unit square to directions, with their densities. Each routine has a χ² test
// in tests/render/sampling_test.cpp.
#pragma once

#include <cmath>

#include "core/vecmath.h"

namespace veduta {

// Cosine-weighted direction in the hemisphere around +z (Malley's method on a concentric disk).
Vec3f sampleCosineHemisphere(Vec2f u);
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0 ? cosTheta * kInvPi : 0.0f; }

// Uniform direction inside the cone around +z whose half-angle θmax has 1 − cos θmax =
// oneMinusCosMax. Cones are given by 1 − cos θmax because small ones (the sun's is 0.27°)
// keep it exact in float, where cos θmax itself rounds to within a few ulps of 1.
Vec3f sampleUniformCone(Vec2f u, float oneMinusCosMax);
inline float uniformConePdf(float oneMinusCosMax) { return 1.0f / (2.0f * kPi * oneMinusCosMax); }

// Uniform point on the unit disk (Shirley-Chiu concentric map).
Vec2f sampleConcentricDisk(Vec2f u);

}  // namespace veduta
