#include "render/chi2.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>

namespace veduta::test {

namespace {

Vec3f directionAt(double cosTheta, double phi) {
    double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    return {float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta)};
}

}  // namespace

Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    int sampleCount, int thetaBins, int phiBins, int subdivisions) {
    // Cells are equal in cos θ and φ, hence equal in solid angle.
    auto cellOf = [&](const Vec3f &d) {
        int i = std::clamp(int((d.z + 1) * 0.5f * float(thetaBins)), 0, thetaBins - 1);
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * M_PI;
        int j = std::clamp(int(phi / (2 * M_PI) * phiBins), 0, phiBins - 1);
        return i * phiBins + j;
    };
    std::vector<double> observed(size_t(thetaBins * phiBins), 0.0), expected(observed.size(), 0.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    Chi2Result result;
    for (int s = 0; s < sampleCount; ++s) {
        Vec3f d = sample({uniform(rng), uniform(rng)});
        if (pdf(d) <= 0) result.outsideSupport += 1.0 / sampleCount;
        observed[size_t(cellOf(d))] += 1;
    }
    // Integrate the density over each cell with a fine midpoint rule.
    double cellSolidAngle = (2.0 / thetaBins) * (2 * M_PI / phiBins);
    for (int i = 0; i < thetaBins; ++i) {
        for (int j = 0; j < phiBins; ++j) {
            double sum = 0;
            for (int a = 0; a < subdivisions; ++a) {
                for (int b = 0; b < subdivisions; ++b) {
                    double cosTheta = -1 + 2.0 * (i + (a + 0.5) / subdivisions) / thetaBins;
                    double phi = 2 * M_PI * (j + (b + 0.5) / subdivisions) / phiBins;
                    sum += pdf(directionAt(cosTheta, phi));
                }
            }
            expected[size_t(i * phiBins + j)] = sum / (subdivisions * subdivisions) * cellSolidAngle * sampleCount;
        }
    }
    // Pool cells expecting fewer than 5 samples into one, as pbrt does.
    std::vector<size_t> order(observed.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pooledObserved = 0, pooledExpected = 0;
    int cells = 0;
    for (size_t k : order) {
        if (expected[k] == 0) {
            if (observed[k] > 0) result.outsideSupport += observed[k] / sampleCount;
            continue;
        }
        if (expected[k] < 5) {
            pooledObserved += observed[k];
            pooledExpected += expected[k];
            continue;
        }
        double diff = observed[k] - expected[k];
        result.statistic += diff * diff / expected[k];
        ++cells;
    }
    if (pooledExpected > 0) {
        double diff = pooledObserved - pooledExpected;
        result.statistic += diff * diff / pooledExpected;
        ++cells;
    }
    result.degreesOfFreedom = cells - 1;
    boost::math::chi_squared distribution(result.degreesOfFreedom);
    result.pValue = boost::math::cdf(boost::math::complement(distribution, result.statistic));
    return result;
}

}  // namespace veduta::test
