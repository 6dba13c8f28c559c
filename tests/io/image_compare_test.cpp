#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include <OpenImageIO/imagebufalgo.h>
#include <unistd.h>

#include "core/error.h"
#include "io/exr_file.h"
#include "io/image_compare.h"

namespace veduta {
namespace {

OIIO::ImageBuf constantImage(int width, int height, std::vector<float> color) {
    OIIO::ImageBuf image(OIIO::ImageSpec(width, height, int(color.size()), OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(image, color);
    return image;
}

// A 64x64 RGB image as the tests' reference.
OIIO::ImageBuf reference() { return constantImage(64, 64, {0.2f, 0.4f, 0.6f}); }

// Adds `delta` to the red channel of the pixels in [x0, x1) x [y0, y1).
void offsetRed(OIIO::ImageBuf &image, int x0, int y0, int x1, int y1, float delta) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) image.setpixel(x, y, {image.getchannel(x, y, 0, 0) + delta, 0.4f, 0.6f});
    }
}

TEST(ImageCompare, IdenticalImagesPassWithZeroFigures) {
    ImageDiff d = compareImages(reference(), reference());
    EXPECT_TRUE(d.passed);
    EXPECT_EQ(d.width, 64);
    EXPECT_EQ(d.height, 64);
    EXPECT_EQ(d.pixels, 4096u);
    EXPECT_EQ(d.channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(d.failedPixels, 0u);
    EXPECT_EQ(d.failedPercent, 0.0);
    EXPECT_EQ(d.meanError, 0.0);
    EXPECT_EQ(d.maxError, 0.0);
    EXPECT_EQ(d.rmse, 0.0);
    EXPECT_EQ(d.relMse, 0.0);
    EXPECT_EQ(d.psnrDb, std::numeric_limits<double>::infinity());
}

TEST(ImageCompare, OnePixelOffByAHalfPassesTheDefaultThresholds) {
    OIIO::ImageBuf a = reference();
    offsetRed(a, 10, 12, 11, 13, 0.5f);
    ImageDiff d = compareImages(a, reference());
    EXPECT_EQ(d.failedPixels, 1u);
    EXPECT_NEAR(d.failedPercent, 100.0 / 4096, 1e-9);
    EXPECT_NEAR(d.maxError, 0.5, 1e-6);
    EXPECT_EQ(d.maxErrorX, 10);
    EXPECT_EQ(d.maxErrorY, 12);
    EXPECT_TRUE(d.passed);
}

TEST(ImageCompare, TwoPercentOfPixelsOffByATenthFail) {
    OIIO::ImageBuf a = reference();
    offsetRed(a, 20, 20, 29, 29, 0.1f);  // 81 pixels: 1.98 %
    ImageDiff d = compareImages(a, reference());
    EXPECT_EQ(d.failedPixels, 81u);
    EXPECT_FALSE(d.passed);

    ImageDiffOptions lenient;
    lenient.failPercent = 2.0;
    EXPECT_TRUE(compareImages(a, reference(), lenient).passed);
    lenient.failThreshold = 0.2;
    lenient.failPercent = 0.0;
    EXPECT_TRUE(compareImages(a, reference(), lenient).passed);
}

TEST(ImageCompare, WarningsAreCountedOnlyWhenAsked) {
    OIIO::ImageBuf a = reference();
    offsetRed(a, 0, 0, 64, 1, 0.01f);  // one row: 1.56 %, below the fail threshold
    ImageDiff quiet = compareImages(a, reference());
    EXPECT_TRUE(quiet.passed);
    EXPECT_FALSE(quiet.warned);
    EXPECT_EQ(quiet.warnedPixels, 0u);

    ImageDiffOptions options;
    options.warnThreshold = 0.005;
    options.warnPercent = 1.0;
    ImageDiff loud = compareImages(a, reference(), options);
    EXPECT_EQ(loud.warnedPixels, 64u);
    EXPECT_TRUE(loud.warned);
    EXPECT_TRUE(loud.passed);
}

TEST(ImageCompare, SizeMismatchThrows) {
    try {
        compareImages(reference(), constantImage(32, 64, {0.2f, 0.4f, 0.6f}));
        FAIL() << "no exception";
    } catch (const std::runtime_error &e) {
        EXPECT_STREQ(e.what(), "sizes differ: A is 64x64, B is 32x64");
    }
}

TEST(ImageCompare, ComparesTheChannelsBothHave) {
    OIIO::ImageBuf rgba = constantImage(4, 4, {0.2f, 0.4f, 0.6f, 1.0f});
    OIIO::ImageBuf rgba2 = constantImage(4, 4, {0.2f, 0.4f, 0.6f, 0.0f});
    OIIO::ImageBuf rgb = constantImage(4, 4, {0.2f, 0.4f, 0.6f});
    EXPECT_EQ(compareImages(rgba, rgb).channels, (std::vector<std::string>{"R", "G", "B"}));
    ImageDiff withAlpha = compareImages(rgba, rgba2);
    EXPECT_EQ(withAlpha.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_EQ(withAlpha.failedPixels, 16u);
    EXPECT_THROW(compareImages(constantImage(4, 4, {0.5f}), constantImage(4, 4, {0.5f})), std::runtime_error);
}

// A render's multilayer EXR as OpenImageIO reads it: the Combined pass of `layer` with `color`,
// and other passes in front of and behind it whose values differ from anything compared.
OIIO::ImageBuf multilayerImage(int width, int height, const std::string &layer, std::vector<float> color) {
    std::vector<std::string> names{layer + ".Depth.Z"};
    for (const char *c : {"R", "G", "B", "A"}) names.push_back(layer + ".Combined." + c);
    names.push_back(layer + ".Normal.X");
    OIIO::ImageSpec spec(width, height, int(names.size()), OIIO::TypeFloat);
    spec.channelnames = names;
    OIIO::ImageBuf image(spec);
    color.insert(color.begin(), 1e10f);
    color.push_back(-0.7f);
    OIIO::ImageBufAlgo::fill(image, color);
    return image;
}

TEST(ImageCompare, MultilayerComparesOnlyItsCombinedPassAsRgba) {
    OIIO::ImageBuf layered = multilayerImage(4, 4, "ViewLayer", {0.2f, 0.4f, 0.6f, 1.0f});
    OIIO::ImageBuf plain = constantImage(4, 4, {0.2f, 0.4f, 0.6f, 1.0f});
    for (const auto &[a, b] : {std::pair{&layered, &plain}, std::pair{&plain, &layered}}) {
        ImageDiff d = compareImages(*a, *b);
        EXPECT_EQ(d.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
        EXPECT_TRUE(d.passed);
        EXPECT_EQ(d.maxError, 0.0);
    }
    // Another layer name, other values in the other passes: still only Combined counts.
    OIIO::ImageBuf other = multilayerImage(4, 4, "RenderLayer", {0.2f, 0.4f, 0.6f, 1.0f});
    OIIO::ImageBufAlgo::fill(other, {5.0f}, OIIO::ROI(0, 4, 0, 4, 0, 1, 0, 1));  // its Depth.Z
    EXPECT_TRUE(compareImages(layered, other).passed);

    OIIO::ImageBuf brighter = multilayerImage(4, 4, "ViewLayer", {0.2f, 0.5f, 0.6f, 1.0f});
    ImageDiff d = compareImages(brighter, plain);
    EXPECT_FALSE(d.passed);
    EXPECT_EQ(d.failedPixels, 16u);
    EXPECT_NEAR(d.maxError, 0.1, 1e-6);
    EXPECT_FALSE(compareImages(plain, brighter).passed);
    EXPECT_FALSE(compareImages(layered, brighter).passed);
}

TEST(ImageCompare, MultilayerWithoutCombinedColourThrowsNamingTheChannel) {
    OIIO::ImageSpec spec(4, 4, 2, OIIO::TypeFloat);
    spec.channelnames = {"ViewLayer.Combined.R", "ViewLayer.Combined.G"};
    OIIO::ImageBuf noBlue(spec);
    try {
        compareImages(noBlue, constantImage(4, 4, {0.2f, 0.4f, 0.6f}));
        FAIL() << "no exception";
    } catch (const std::runtime_error &e) {
        EXPECT_STREQ(e.what(),
                     "A has no ViewLayer.Combined.B channel (it has ViewLayer.Combined.R, ViewLayer.Combined.G)");
    }
}

// Worked by hand: pixel 0 equal; pixel 1 off by 0.1, 0.2, 0.3 against a reference of 0.1, 0.2, 0.
TEST(ImageCompare, KnownFiguresOnATinyImage) {
    OIIO::ImageBuf a(OIIO::ImageSpec(2, 1, 3, OIIO::TypeFloat)), b(OIIO::ImageSpec(2, 1, 3, OIIO::TypeFloat));
    a.setpixel(0, 0, {0.5f, 0.5f, 0.5f});
    b.setpixel(0, 0, {0.5f, 0.5f, 0.5f});
    a.setpixel(1, 0, {0.0f, 0.0f, 0.3f});
    b.setpixel(1, 0, {0.1f, 0.2f, 0.0f});
    ImageDiff d = compareImages(a, b);
    EXPECT_NEAR(d.meanError, 0.6 / 6, 1e-7);
    EXPECT_NEAR(d.maxError, 0.3, 1e-7);
    EXPECT_EQ(d.maxErrorX, 1);
    EXPECT_EQ(d.maxErrorY, 0);
    EXPECT_NEAR(d.rmse, std::sqrt(0.14 / 6), 1e-7);
    // (0.01 / 0.02 + 0.04 / 0.05 + 0.09 / 0.01) / 6
    EXPECT_NEAR(d.relMse, (0.5 + 0.8 + 9.0) / 6, 1e-6);
    EXPECT_NEAR(d.psnrDb, 10 * std::log10(6 / 0.14), 1e-5);
    EXPECT_EQ(d.failedPixels, 1u);
    EXPECT_FALSE(d.passed);  // one pixel of two

    ImageDiffOptions relMse;
    relMse.metric = DiffMetric::RelMse;
    relMse.maxRelMse = 1.8;
    EXPECT_TRUE(compareImages(a, b, relMse).passed);
    relMse.maxRelMse = 1.7;
    EXPECT_FALSE(compareImages(a, b, relMse).passed);
}

TEST(ImageCompare, NanAgainstANumberFails) {
    OIIO::ImageBuf a = reference();
    a.setpixel(3, 4, {std::numeric_limits<float>::quiet_NaN(), 0.4f, 0.6f});
    ImageDiff d = compareImages(a, reference());
    EXPECT_EQ(d.failedPixels, 1u);
    EXPECT_EQ(d.maxError, std::numeric_limits<double>::infinity());
    EXPECT_EQ(d.maxErrorX, 3);
    EXPECT_EQ(d.maxErrorY, 4);
    EXPECT_TRUE(compareImages(a, a).passed);
}

TEST(ImageCompare, MetricsWithoutTheirInputsThrow) {
    ImageDiffOptions options;
    options.metric = DiffMetric::RelMse;
    EXPECT_THROW(compareImages(reference(), reference(), options), std::invalid_argument);
    options.metric = DiffMetric::ZTest;
    EXPECT_THROW(compareImages(reference(), reference(), options), std::invalid_argument);
    OIIO::ImageBuf variance = constantImage(64, 64, {0.1f, 0.1f, 0.1f});
    options.referenceVariance = &variance;  // but no samples per pixel
    EXPECT_THROW(compareImages(reference(), reference(), options), std::invalid_argument);
}

// A: the mean of `spp` samples of a per-sample variance `variance` around B, plus `bias`.
OIIO::ImageBuf noisyMean(const OIIO::ImageBuf &b, float variance, uint32_t spp, float bias) {
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, std::sqrt(variance / float(spp)));
    OIIO::ImageBuf a(b);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            float p[3];
            for (int c = 0; c < 3; ++c) p[c] = b.getchannel(x, y, 0, c) + bias + noise(rng);
            a.setpixel(x, y, p);
        }
    }
    return a;
}

TEST(ImageCompare, ZTestAcceptsNoiseAndRejectsBias) {
    const float variance = 0.04f;  // per sample: σ = 0.2, so σ of a 16-sample mean = 0.05
    const uint32_t spp = 16;
    OIIO::ImageBuf b = reference(), var = constantImage(64, 64, {variance, variance, variance});
    ImageDiffOptions options;
    options.metric = DiffMetric::ZTest;
    options.referenceVariance = &var;
    options.samplesPerPixel = spp;

    ImageDiff unbiased = compareImages(noisyMean(b, variance, spp, 0.0f), b, options);
    ASSERT_TRUE(unbiased.zTestPassFraction);
    EXPECT_GE(*unbiased.zTestPassFraction, kZTestMinPassFraction);
    EXPECT_TRUE(unbiased.passed);

    ImageDiff biased = compareImages(noisyMean(b, variance, spp, 4 * 0.05f), b, options);
    EXPECT_LT(*biased.zTestPassFraction, kZTestMinPassFraction);
    EXPECT_FALSE(biased.passed);

    // The same noise with four times the samples claimed is too much noise.
    options.samplesPerPixel = 4 * spp;
    EXPECT_FALSE(compareImages(noisyMean(b, variance, spp, 0.0f), b, options).passed);
}

class ImageCompareFiles : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::path(testing::TempDir()) / ("veduta_image_compare_" + std::to_string(getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string write(const OIIO::ImageBuf &image, const std::string &name) {
        std::string path = (dir_ / name).string();
        EXPECT_TRUE(image.write(path)) << image.geterror();
        return path;
    }

    std::filesystem::path dir_;
};

TEST_F(ImageCompareFiles, ComparesFilesAndSeesRewrites) {
    std::string a = write(reference(), "a.exr"), b = write(reference(), "b.exr");
    EXPECT_TRUE(compareImages(a, b).passed);
    // Rewritten under the same name: the new pixels count, not a cached copy of the old ones.
    write(constantImage(64, 64, {0.9f, 0.4f, 0.6f}), "b.exr");
    EXPECT_FALSE(compareImages(a, b).passed);
}

// A file as `veduta render` writes it, against an old plain RGBA golden, through the files.
TEST_F(ImageCompareFiles, RenderMultilayerExrComparesWithPlainRgbaExr) {
    LayeredImage render;
    render.fullWidth = 6;
    render.fullHeight = 4;
    render.dataWindow = {0, 0, 6, 4};
    const std::vector<float> rgba{0.25f, 0.5f, 0.75f, 1.0f};
    const char *names[] = {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
                           "ViewLayer.Combined.A"};
    render.addChannel("ViewLayer.Depth.Z").assign(render.dataWindow.area(), 1e10f);
    for (size_t c = 0; c < 4; ++c) render.addChannel(names[c]).assign(render.dataWindow.area(), rgba[c]);
    render.addChannel("ViewLayer.SampleCount.X").assign(render.dataWindow.area(), 16.0f);
    std::string layered = (dir_ / "render.exr").string();
    writeExr(render, layered);
    std::string plain = write(constantImage(6, 4, rgba), "golden.exr");

    ImageDiff d = compareImages(layered, plain);
    EXPECT_EQ(d.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
    EXPECT_TRUE(d.passed);
    EXPECT_EQ(d.maxError, 0.0);
    write(constantImage(6, 4, {0.25f, 0.5f, 0.95f, 1.0f}), "golden.exr");
    d = compareImages(plain, layered);
    EXPECT_FALSE(d.passed);
    EXPECT_NEAR(d.maxError, 0.2, 1e-6);
}

TEST_F(ImageCompareFiles, UnreadableFileThrowsInputErrorNamingIt) {
    std::string bad = (dir_ / "bad.exr").string();
    std::ofstream(bad) << "not an image";
    try {
        readImage(bad);
        FAIL() << "no exception";
    } catch (const InputError &e) {
        EXPECT_EQ(e.loc().file, bad);
    }
}

TEST_F(ImageCompareFiles, DiffImageIsScaledBySixteenInEightBits) {
    OIIO::ImageBuf a = constantImage(8, 4, {0.2f, 0.4f, 0.6f, 1.0f});
    OIIO::ImageBuf b = constantImage(8, 4, {0.21f, 0.4f, 0.5f, 0.0f});
    std::filesystem::path out = dir_ / "sub" / "diff.png";
    writeDiffImage(a, b, out);
    OIIO::ImageBuf diff = readImage(out.string());
    ASSERT_EQ(diff.nchannels(), 3);
    EXPECT_EQ(diff.spec().width, 8);
    EXPECT_NEAR(diff.getchannel(5, 2, 0, 0), std::round(0.16 * 255) / 255, 1e-6);
    EXPECT_EQ(diff.getchannel(5, 2, 0, 1), 0.0f);
    EXPECT_EQ(diff.getchannel(5, 2, 0, 2), 1.0f);  // 1.6, clamped
    // The same from a multilayer A: its Combined pass, not its first three channels.
    writeDiffImage(multilayerImage(8, 4, "ViewLayer", {0.2f, 0.4f, 0.6f, 1.0f}), b, out);
    diff = readImage(out.string());
    EXPECT_NEAR(diff.getchannel(5, 2, 0, 0), std::round(0.16 * 255) / 255, 1e-6);
    EXPECT_EQ(diff.getchannel(5, 2, 0, 1), 0.0f);
    EXPECT_EQ(diff.getchannel(5, 2, 0, 2), 1.0f);
    for (const auto &entry : std::filesystem::directory_iterator(out.parent_path())) {
        EXPECT_EQ(entry.path().filename(), "diff.png") << "a temporary was left behind";
    }
}

}  // namespace
}  // namespace veduta
