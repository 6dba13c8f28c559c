#include "compare/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/rel_mse.h"
#include "io/output_files.h"

namespace veduta {

namespace {

float displayValue(float linear) { return std::isfinite(linear) ? std::clamp(linearToSrgb(linear), 0.0f, 1.0f) : 0.0f; }

// A separable Gaussian blur with the window clipped and renormalised at the borders.
std::vector<double> blurred(const std::vector<double> &image, int width, int height) {
    constexpr int kRadius = 5;
    constexpr double kSigma = 1.5;
    double weights[2 * kRadius + 1];
    for (int i = -kRadius; i <= kRadius; ++i) weights[i + kRadius] = std::exp(-i * i / (2 * kSigma * kSigma));
    std::vector<double> rows(image.size()), out(image.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0, norm = 0;
            for (int i = std::max(-kRadius, -x); i <= std::min(kRadius, width - 1 - x); ++i) {
                sum += weights[i + kRadius] * image[size_t(y) * size_t(width) + size_t(x + i)];
                norm += weights[i + kRadius];
            }
            rows[size_t(y) * size_t(width) + size_t(x)] = sum / norm;
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0, norm = 0;
            for (int i = std::max(-kRadius, -y); i <= std::min(kRadius, height - 1 - y); ++i) {
                sum += weights[i + kRadius] * rows[size_t(y + i) * size_t(width) + size_t(x)];
                norm += weights[i + kRadius];
            }
            out[size_t(y) * size_t(width) + size_t(x)] = sum / norm;
        }
    return out;
}

}  // namespace

std::vector<float> displayLuma(const RgbaImage &image) {
    std::vector<float> luma(size_t(image.width()) * size_t(image.height()));
    const float *p = image.rgba();
    for (size_t i = 0; i < luma.size(); ++i)
        luma[i] = 0.2126f * displayValue(p[4 * i]) + 0.7152f * displayValue(p[4 * i + 1]) +
            0.0722f * displayValue(p[4 * i + 2]);
    return luma;
}

double ssim(const std::vector<float> &a, const std::vector<float> &b, int width, int height) {
    if (a.size() != b.size() || a.size() != size_t(width) * size_t(height))
        throw std::invalid_argument("ssim: the images differ in size");
    if (a.empty()) return 1;
    constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
    std::vector<double> x(a.begin(), a.end()), y(b.begin(), b.end()), xx(a.size()), yy(a.size()), xy(a.size());
    for (size_t i = 0; i < a.size(); ++i) xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
    std::vector<double> mx = blurred(x, width, height), my = blurred(y, width, height);
    std::vector<double> sxx = blurred(xx, width, height), syy = blurred(yy, width, height),
                        sxy = blurred(xy, width, height);
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        double vx = std::max(0.0, sxx[i] - mx[i] * mx[i]), vy = std::max(0.0, syy[i] - my[i] * my[i]);
        double cxy = sxy[i] - mx[i] * my[i];
        sum += (2 * mx[i] * my[i] + kC1) * (2 * cxy + kC2) / ((mx[i] * mx[i] + my[i] * my[i] + kC1) * (vx + vy + kC2));
    }
    return sum / double(a.size());
}

ImageMetrics compareRenderings(const RgbaImage &reference, const RgbaImage &test) {
    if (reference.width() != test.width() || reference.height() != test.height())
        throw std::invalid_argument("compareRenderings: the images differ in size");
    ImageMetrics m;
    const float *r = reference.rgba(), *t = test.rgba();
    size_t pixels = size_t(reference.width()) * size_t(reference.height());
    double rel = 0, squared = 0;
    for (size_t i = 0; i < pixels; ++i)
        for (size_t c = 0; c < 3; ++c) {
            float rv = std::isfinite(r[4 * i + c]) ? r[4 * i + c] : 0.0f;
            float tv = std::isfinite(t[4 * i + c]) ? t[4 * i + c] : 0.0f;
            rel += relMseTerm(tv, rv);
            double d = displayValue(tv) - displayValue(rv);
            squared += d * d;
        }
    double samples = double(std::max<size_t>(1, pixels * 3));
    m.relMse = rel / samples;
    double mse = squared / samples;
    m.psnr = mse > 0 ? 10 * std::log10(1 / mse) : std::numeric_limits<double>::infinity();
    m.ssim = ssim(displayLuma(reference), displayLuma(test), reference.width(), reference.height());
    return m;
}

double silhouetteIou(const std::vector<uint32_t> &a, const std::vector<uint32_t> &b) {
    if (a.size() != b.size()) throw std::invalid_argument("silhouetteIou: the masks differ in size");
    size_t both = 0, either = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        both += a[i] != 0 && b[i] != 0;
        either += a[i] != 0 || b[i] != 0;
    }
    return either == 0 ? 1.0 : double(both) / double(either);
}

}  // namespace veduta
