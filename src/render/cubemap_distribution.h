// Importance sampling of a cubemap environment: directions drawn in proportion to the
// radiance the cubemap's bilinear lookup gives, with their solid-angle densities for
// next-event estimation and MIS against BSDF sampling.
#pragma once

#include <vector>

#include "core/vecmath.h"
#include "scene/cubemap.h"

namespace veduta {

struct EnvironmentSample {
    Vec3f direction;  // unit, in the cubemap's frame
    float pdf = 0;    // per unit solid angle
};

class CubemapDistribution {
  public:
    explicit CubemapDistribution(const Cubemap &cubemap);

    // u ∈ [0, 1)², from the caller's sampler: no random numbers are drawn here.
    EnvironmentSample sample(Vec2f u) const;
    // The density `sample` draws a unit direction with; positive wherever the cubemap's lookup
    // is, 0 in texels whose whole neighbourhood is black.
    float pdf(const Vec3f &direction) const;

  private:
    int size_ = 0;
    // The texel's probability per unit area of the face plane, at distance 1 from the centre.
    std::vector<float> texelDensity_;  // indexed (face · size + y) · size + x
    std::vector<double> rowCdf_;       // over the 6·size rows (face · size + y), 6·size + 1 entries
    std::vector<double> columnCdf_;    // per row, over its texels: size + 1 entries each

    float density(int face, int x, int y, float a, float b) const;
};

}  // namespace veduta
