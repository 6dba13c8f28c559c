// Pearson's χ² test of a direction sampler against its density, as pbrt-v4 and Mitsuba test
// theirs: sample histogram over a (cos θ, φ) grid versus the density integrated per cell,
// cells with small expected counts pooled.
#pragma once

#include <functional>

#include "core/vecmath.h"

namespace veduta::test {

struct Chi2Result {
    double statistic = 0;
    int degreesOfFreedom = 0;
    double pValue = 0;
    double outsideSupport = 0;  // fraction of samples where the density is 0
};

// `sample` maps a point of the unit square to a unit direction; `pdf` is its density in
// solid angle. Uses `sampleCount` uniform random points from a fixed-seed generator. Each
// cell's expected count integrates `pdf` at subdivisions² points; densities with jumps
// inside cells (piecewise-constant ones) need more than smooth ones.
Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    int sampleCount = 1000000, int thetaBins = 40, int phiBins = 80, int subdivisions = 8);

}  // namespace veduta::test
