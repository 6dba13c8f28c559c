#include "render/cubemap_distribution.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/color.h"

namespace veduta {

namespace {

// The mean of the bilinear lookup's luminance over a texel: 9/16 of the texel itself, 3/32 of
// each edge neighbour and 1/64 of each diagonal one, across face edges as the lookup reads
// them. This rather than the maximum over the 3×3 neighbourhood, or a share of uniform
// sampling: it is positive wherever the lookup is (every tap the lookup can read inside the
// texel has a positive weight), which MIS needs to stay unbiased, and it gives each texel
// the share of light the lookup actually spreads there, where the maximum would weight a
// one-texel sun's eight neighbours like the sun and a uniform share would draw few samples
// where the lookup's blur is bright.
float meanLookupLuminance(const Cubemap &cube, int face, int x, int y) {
    constexpr float kWeights[3] = {1.0f / 8, 3.0f / 4, 1.0f / 8};  // the 1D tent integrated over a texel
    float sum = 0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            sum += kWeights[dx + 1] * kWeights[dy + 1] * luminance(cube.texelAcrossEdges(face, x + dx, y + dy));
        }
    }
    return sum;
}

// The row or column whose CDF interval holds u, and u rescaled to [0, 1) within it. Rows
// and columns of probability 0 have empty intervals and are never chosen.
int sampleCdf(const double *cdf, int count, float u, float &remapped) {
    int i = int(std::upper_bound(cdf, cdf + count + 1, double(u)) - cdf) - 1;
    i = std::clamp(i, 0, count - 1);
    double width = cdf[i + 1] - cdf[i];
    remapped = std::min(float((double(u) - cdf[i]) / width), std::nextafter(1.0f, 0.0f));
    return i;
}

}  // namespace

CubemapDistribution::CubemapDistribution(const Cubemap &cubemap) : size_(cubemap.size()) {
    int n = size_, rows = kCubeFaceCount * n;
    std::vector<double> solidAngle(size_t(n) * size_t(n));
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) solidAngle[size_t(y * n + x)] = cubeTexelSolidAngle(n, x, y);
    }
    // Each row is summed on its own, in order, so the result does not depend on the threads.
    std::vector<double> weight(size_t(rows) * size_t(n)), rowSum(static_cast<size_t>(rows));
    auto weighRows = [&](bool uniform) {
        tbb::parallel_for(0, rows, [&](int row) {
            int face = row / n, y = row % n;
            double sum = 0;
            for (int x = 0; x < n; ++x) {
                double w = solidAngle[size_t(y * n + x)];
                if (!uniform) w *= meanLookupLuminance(cubemap, face, x, y);
                weight[size_t(row) * size_t(n) + size_t(x)] = w;
                sum += w;
            }
            rowSum[size_t(row)] = sum;
        });
    };
    weighRows(false);
    double total = 0;
    for (double s : rowSum) total += s;
    // A black environment has nothing to sample; uniform directions keep pdf and sample
    // defined (the caller's estimates are 0 either way).
    if (!(total > 0)) {
        weighRows(true);
        total = 0;
        for (double s : rowSum) total += s;
    }

    double texelArea = 4.0 / (double(n) * double(n));
    texelDensity_.resize(weight.size());
    rowCdf_.assign(size_t(rows) + 1, 0.0);
    columnCdf_.assign(size_t(rows) * size_t(n + 1), 0.0);
    tbb::parallel_for(0, rows, [&](int row) {
        double *cdf = &columnCdf_[size_t(row) * size_t(n + 1)];
        double prefix = 0;
        for (int x = 0; x < n; ++x) {
            double w = weight[size_t(row) * size_t(n) + size_t(x)];
            texelDensity_[size_t(row) * size_t(n) + size_t(x)] = float(w / total / texelArea);
            prefix += w;
            cdf[x + 1] = rowSum[size_t(row)] > 0 ? prefix / rowSum[size_t(row)] : 0.0;
        }
        if (rowSum[size_t(row)] > 0) cdf[n] = 1;
    });
    double prefix = 0;
    for (int row = 0; row < rows; ++row) {
        prefix += rowSum[size_t(row)];
        rowCdf_[size_t(row) + 1] = prefix / total;
    }
    rowCdf_[size_t(rows)] = 1;
}

float CubemapDistribution::density(int face, int x, int y, float a, float b) const {
    // Uniform on the face plane within the texel; dA/dω = (1 + a² + b²)^(3/2) there.
    float d = texelDensity_[(size_t(face) * size_t(size_) + size_t(y)) * size_t(size_) + size_t(x)];
    float r2 = 1 + a * a + b * b;
    return d * r2 * std::sqrt(r2);
}

EnvironmentSample CubemapDistribution::sample(Vec2f u) const {
    float inRow, inColumn;
    int row = sampleCdf(rowCdf_.data(), kCubeFaceCount * size_, u.x, inRow);
    int x = sampleCdf(&columnCdf_[size_t(row) * size_t(size_ + 1)], size_, u.y, inColumn);
    int face = row / size_, y = row % size_;
    // Rounding must not carry the point into the next texel, whose density differs.
    float px = std::min(float(x) + inColumn, std::nextafter(float(x + 1), 0.0f));
    float py = std::min(float(y) + inRow, std::nextafter(float(y + 1), 0.0f));
    float a = cubeFaceCoordinate(px, size_), b = -cubeFaceCoordinate(py, size_);
    return {cubeDirection(size_, face, px, py), density(face, x, y, a, b)};
}

float CubemapDistribution::pdf(const Vec3f &direction) const {
    CubeTexel t = cubeLocate(size_, direction);
    float a = cubeFaceCoordinate(t.x, size_), b = -cubeFaceCoordinate(t.y, size_);
    return density(t.face, int(t.x), int(t.y), a, b);
}

}  // namespace veduta
