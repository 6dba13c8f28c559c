// Pearson's χ² test of a direction sampler against its density, as pbrt-v4 and Mitsuba test
// theirs: sample histogram over a (θ, φ) grid versus the density integrated per cell,
// cells with small expected counts pooled.
#pragma once

#include <cstdint>
#include <functional>

#include "core/vecmath.h"

namespace veduta::test {

struct Chi2Result {
    double statistic = 0;
    int degreesOfFreedom = 0;
    double pValue = 0;
    double outsideSupport = 0;  // fraction of samples where the density is 0
};

struct Chi2Options {
    int sampleCount = 1000000;
    int thetaBins = 40;
    int phiBins = 80;
    // Bins equal in θ rather than in cos θ (equal solid angle): near the pole they are far
    // finer, which resolves a narrow lobe placed there with `frame`.
    bool equalAngleBins = false;
    // Points per cell side for integrating the density: densities that jump inside cells
    // (piecewise-constant ones) need more than smooth ones.
    int subdivisions = 8;
    // Whether `sample` may decline (return the zero vector), as BSDFs do below the surface.
    // The missing mass then forms one more cell; otherwise it is not tested, since for a
    // density that integrates to 1 it would only hold the integration rule's error.
    bool declines = false;
    // The grid's pole is frame.n.
    Frame frame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    // Of the uniform points: tests that share a seed share their samples, and their p-values
    // are then not independent.
    uint32_t seed = 7;
};

// `sample` maps a point of the unit square to a unit direction, or to the zero vector when it
// declines (a direction below the surface, say); `pdf` is the density in solid angle of the
// directions it returns, so declined samples make it integrate to less than 1. They form one
// more cell, whose expected count is that missing mass. Uses `sampleCount` uniform random
// points from a generator seeded with `seed` (7 for the second form).
Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    const Chi2Options &options);
Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    int sampleCount = 1000000, int thetaBins = 40, int phiBins = 80);

}  // namespace veduta::test
