// Known answers of the image measures of `veduta compare`: equal images, a uniform step in the
// display encoding (PSNR and SSIM by hand), and overlapping silhouettes.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/image_metrics.h"

namespace veduta {
namespace {

// The linear value whose sRGB encoding is `v`.
float fromSrgb(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

RgbaImage uniform(float srgb, int width = 32, int height = 24) {
    RgbaImage image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, Vec3f{1, 1, 1} * fromSrgb(srgb));
    return image;
}

TEST(ImageMetrics, AnImageAgainstItself) {
    RgbaImage a = uniform(0.5f);
    a.set(3, 4, {2.0f, 0.1f, 0.0f});
    ImageMetrics m = compareRenderings(a, a);
    EXPECT_EQ(m.relMse, 0);
    EXPECT_TRUE(std::isinf(m.psnr));
    EXPECT_DOUBLE_EQ(m.ssim, 1);
}

TEST(ImageMetrics, AUniformStepOfATenth) {
    ImageMetrics m = compareRenderings(uniform(0.5f), uniform(0.6f));
    // MSE 0.01 of the display values: 10 log10(1 / 0.01) = 20 dB.
    EXPECT_NEAR(m.psnr, 20, 1e-4);
    // No variance anywhere: SSIM is its luminance term, (2·0.5·0.6 + C1) / (0.5² + 0.6² + C1).
    double c1 = 1e-4;
    EXPECT_NEAR(m.ssim, (0.6 + c1) / (0.61 + c1), 1e-5);
    // relMSE of the linear values against the reference's.
    double r = fromSrgb(0.5f), t = fromSrgb(0.6f);
    EXPECT_NEAR(m.relMse, (t - r) * (t - r) / (r * r + 1e-2), 1e-6);
}

TEST(ImageMetrics, SsimSeesStructure) {
    // The same mean, the pattern inverted: SSIM falls far below the uniform step's.
    RgbaImage a(32, 32), b(32, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            bool on = (x / 4 + y / 4) % 2 == 0;
            a.set(x, y, Vec3f{1, 1, 1} * fromSrgb(on ? 0.8f : 0.2f));
            b.set(x, y, Vec3f{1, 1, 1} * fromSrgb(on ? 0.2f : 0.8f));
        }
    EXPECT_LT(compareRenderings(a, b).ssim, 0);
}

TEST(ImageMetrics, ImagesOfTwoSizesAreRefused) {
    EXPECT_THROW(compareRenderings(uniform(0.5f, 8, 8), uniform(0.5f, 8, 9)), std::invalid_argument);
}

TEST(ImageMetrics, SilhouetteIou) {
    std::vector<uint32_t> a(20, 0), b(20, 0);
    for (int i = 0; i < 10; ++i) a[i] = 3;
    for (int i = 5; i < 15; ++i) b[i] = 9;  // another id: a silhouette is any building
    EXPECT_DOUBLE_EQ(silhouetteIou(a, b), 5.0 / 15.0);
    EXPECT_DOUBLE_EQ(silhouetteIou(a, a), 1);
    EXPECT_DOUBLE_EQ(silhouetteIou(std::vector<uint32_t>(4, 0), std::vector<uint32_t>(4, 0)), 1);
}

}  // namespace
}  // namespace veduta
