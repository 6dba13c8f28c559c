#include "render/chi2.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>

namespace veduta::test {

namespace {

// The grid: rows in cos θ or θ, columns in φ, around options.frame.n.
class Grid {
  public:
    explicit Grid(const Chi2Options &o) : o_(o) {}

    size_t cellCount() const { return size_t(o_.thetaBins * o_.phiBins); }

    size_t cellOf(const Vec3f &direction) const {
        Vec3f d = o_.frame.toLocal(direction);
        double cosTheta = std::clamp(double(d.z), -1.0, 1.0);
        double row = o_.equalAngleBins ? std::acos(cosTheta) / M_PI : 1 - (cosTheta + 1) * 0.5;
        int i = std::clamp(int(row * o_.thetaBins), 0, o_.thetaBins - 1);
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * M_PI;
        int j = std::clamp(int(phi / (2 * M_PI) * o_.phiBins), 0, o_.phiBins - 1);
        return size_t(i * o_.phiBins + j);
    }

    // ∫ pdf dω over cell (i, j) by a kSub × kSub midpoint rule in (θ or cos θ, φ); `zeros`
    // counts the points where the density is 0.
    double integrate(const std::function<float(const Vec3f &)> &pdf, int i, int j, int kSub, int &zeros) const {
        double dPhi = 2 * M_PI / o_.phiBins, sum = 0;
        zeros = 0;
        for (int a = 0; a < kSub; ++a) {
            double row = (i + (a + 0.5) / kSub) / o_.thetaBins;
            double cosTheta, weight;  // weight: dω per unit of the row variable and of φ
            if (o_.equalAngleBins) {
                cosTheta = std::cos(row * M_PI);
                weight = std::sin(row * M_PI) * M_PI;
            } else {
                cosTheta = 1 - 2 * row;
                weight = 2;
            }
            double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
            for (int b = 0; b < kSub; ++b) {
                double phi = dPhi * (j + (b + 0.5) / kSub);
                Vec3f local{float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta)};
                float p = pdf(o_.frame.toWorld(local));
                zeros += p <= 0;
                sum += p * weight;
            }
        }
        return sum / (kSub * kSub) * dPhi / o_.thetaBins;
    }

  private:
    const Chi2Options &o_;
};

}  // namespace

Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    int sampleCount, int thetaBins, int phiBins) {
    Chi2Options options;
    options.sampleCount = sampleCount;
    options.thetaBins = thetaBins;
    options.phiBins = phiBins;
    return chi2Test(sample, pdf, options);
}

Chi2Result chi2Test(const std::function<Vec3f(Vec2f)> &sample, const std::function<float(const Vec3f &)> &pdf,
                    const Chi2Options &options) {
    Grid grid(options);
    // The last cell holds the declined samples.
    size_t declinedCell = grid.cellCount();
    std::vector<double> observed(declinedCell + 1, 0.0), expected(observed.size(), 0.0);
    std::mt19937 rng(options.seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    Chi2Result result;
    double n = options.sampleCount;
    for (int s = 0; s < options.sampleCount; ++s) {
        Vec3f d = sample({uniform(rng), uniform(rng)});
        if (d == Vec3f(0.0f)) {
            observed[declinedCell] += 1;
            continue;
        }
        if (pdf(d) <= 0) result.outsideSupport += 1.0 / n;
        observed[grid.cellOf(d)] += 1;
    }
    // Where the support ends inside a cell (a horizon), the coarse rule misjudges its share by
    // up to a row of points, and misses slivers entirely: such cells, and the empty cells
    // beside them, are integrated again, 64 × 64 or finer.
    int rows = options.thetaBins, columns = options.phiBins;
    std::vector<int> zeros(grid.cellCount());
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            size_t k = size_t(i * columns + j);
            expected[k] = grid.integrate(pdf, i, j, options.subdivisions, zeros[k]) * n;
        }
    }
    std::vector<double> coarse = expected;
    auto holdsSupport = [&](int i, int j) {
        return i >= 0 && i < rows && coarse[size_t(i * columns + (j + columns) % columns)] > 0;
    };
    double total = 0;
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            size_t k = size_t(i * columns + j);
            bool edge = zeros[k] > 0 &&
                (coarse[k] > 0 || holdsSupport(i - 1, j) || holdsSupport(i + 1, j) || holdsSupport(i, j - 1) ||
                 holdsSupport(i, j + 1));
            int unused;
            if (edge) expected[k] = grid.integrate(pdf, i, j, std::max(64, options.subdivisions), unused) * n;
            total += expected[k];
        }
    }
    expected[declinedCell] = options.declines ? std::max(0.0, n - total) : 0.0;
    if (!options.declines) result.outsideSupport += observed[declinedCell] / n;
    // Pool cells expecting fewer than 5 samples into one, as pbrt does.
    std::vector<size_t> order(observed.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pooledObserved = 0, pooledExpected = 0;
    int cells = 0;
    for (size_t k : order) {
        // A cell the midpoint rule sees as empty may still hold a sliver of the support (at a
        // horizon cutting through it); samples where the density is 0 are counted above.
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
