// Images made in memory (baked masonry) as textures: held whole with mip levels made as maketx
// makes them, so that they filter as the same image written to a file and added from there would;
// equal images share an id; past the memory budget they go through the cache like files.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/hash.h"
#include "images/color_config.h"
#include "images/image_files.h"
#include "images/oiio_textures.h"
#include "images/resident_texture.h"

namespace veduta {
namespace {

// An image of odd size (so that mip levels average fractions of texels) with a smooth part and a
// noisy part, deterministic.
Image testImage(int width, int height, int channels, uint32_t seed) {
    Image image(width, height, channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.at(x, y)[c] = 0.3f * float(x + c) / float(width) + 0.2f * float(y) / float(height) +
                    0.5f * bitsToUnitFloat(hashValues({seed, uint32_t(x), uint32_t(y), uint32_t(c)}));
    return image;
}

class ImageTexturesTest : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("veduta-image-textures-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    size_t cachedFiles() const {
        size_t count = 0;
        for (const auto &entry : std::filesystem::recursive_directory_iterator(dir_ / "cache"))
            count += entry.is_regular_file();
        return count;
    }

    std::filesystem::path dir_;
    std::shared_ptr<const ColorConfig> config_ = ColorConfig::load();
};

// The exact mean of `image`'s channel `c` over columns [x0, x1) and rows [y0, y1), fractions of
// texels weighed by the part covered.
double areaMean(const Image &image, int c, double x0, double x1, double y0, double y1) {
    double sum = 0;
    for (int y = int(std::floor(y0)); y < int(std::ceil(y1)); ++y)
        for (int x = int(std::floor(x0)); x < int(std::ceil(x1)); ++x) {
            double w =
                (std::min(x1, x + 1.0) - std::max(x0, double(x))) * (std::min(y1, y + 1.0) - std::max(y0, double(y)));
            sum += w * image.at(x, y)[c];
        }
    return sum / ((x1 - x0) * (y1 - y0));
}

TEST_F(ImageTexturesTest, AnImageFiltersAsItsFileAtTheFirstLevelAndByAreaMeansBelow) {
    const Image image = testImage(37, 23, 4, 1);
    std::filesystem::path file = dir_ / "image.exr";
    writeImageFile(file, image, *config_);
    OiioTextures textures(dir_ / "cache", config_);
    TextureId fromFile = textures.add(file, "");
    TextureId inMemory = textures.add(image);
    ASSERT_NE(fromFile, inMemory);
    EXPECT_EQ(textures.channels(inMemory), 4);
    // At a tiny footprint, the first level, bilinear: the file's texels exactly.
    double worstTiny = 0;
    for (uint32_t i = 0; i < 2000; ++i) {
        float u = bitsToUnitFloat(hashValues({4, i})) * 3 - 1, v = bitsToUnitFloat(hashValues({5, i})) * 3 - 1;
        float ours[4], theirs[4];
        textures.lookup(inMemory, {u, v}, 1e-5f, ours, 4);
        textures.lookup(fromFile, {u, v}, 1e-5f, theirs, 4);
        for (int c = 0; c < 4; ++c) worstTiny = std::max(worstTiny, double(std::abs(ours[c] - theirs[c])));
    }
    EXPECT_LT(worstTiny, 1e-6);
    // At the centres of a deeper level's texels, with the footprint of that level: each texel the
    // mean of the area of the level above it covers (maketx's box filter drifts from that at odd
    // sizes, so the file's levels are no reference here). Level sizes halve, rounding down.
    Image above = image;
    for (int level = 1; level <= 3; ++level) {
        Image expected(std::max(1, above.width / 2), std::max(1, above.height / 2), 4);
        double rx = double(above.width) / expected.width, ry = double(above.height) / expected.height;
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < expected.width; ++x)
                for (int c = 0; c < 4; ++c)
                    expected.at(x, y)[c] = float(areaMean(above, c, x * rx, (x + 1) * rx, y * ry, (y + 1) * ry));
        float footprint = std::exp2(float(level)) / 37.0f;
        double worst = 0;
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < expected.width; ++x) {
                float out[4];
                Vec2f centre{(x + 0.5f) / float(expected.width), 1.0f - (y + 0.5f) / float(expected.height)};
                textures.lookup(inMemory, centre, footprint, out, 4);
                for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(out[c] - expected.at(x, y)[c])));
            }
        std::printf("level %d (%d x %d): largest difference from the area means %.2e\n", level, expected.width,
                    expected.height, worst);
        EXPECT_LT(worst, 1e-5) << level;
        above = expected;
    }
}

TEST_F(ImageTexturesTest, EqualImagesShareAnIdAndAFingerprintWithoutAFile) {
    OiioTextures textures(dir_ / "cache", config_);
    TextureId a = textures.add(testImage(16, 9, 3, 1));
    EXPECT_EQ(textures.add(testImage(16, 9, 3, 1)), a);
    TextureId b = textures.add(testImage(16, 9, 3, 2));
    EXPECT_NE(b, a);
    EXPECT_NE(textures.fingerprint(a), textures.fingerprint(b));
    TextureId c = textures.add(testImage(9, 16, 3, 1));  // the same values in another shape
    EXPECT_NE(textures.fingerprint(c), textures.fingerprint(a));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "cache"));
    EXPECT_THROW(textures.add(Image()), std::invalid_argument);
    EXPECT_THROW(textures.add(Image(2, 2, 5)), std::invalid_argument);
}

TEST_F(ImageTexturesTest, PastTheMemoryBudgetAnImageIsStreamedFromTheCache) {
    const Image image = testImage(37, 23, 4, 3);
    // Room for the first image's levels and not for a second.
    OiioTextures textures(dir_ / "cache", config_, ResidentTexture::bytesFor(37, 23, 4));
    TextureId held = textures.add(image);
    TextureId streamed = textures.add(testImage(37, 23, 4, 4));
    EXPECT_EQ(cachedFiles(), 1u);
    OiioTextures again(dir_ / "cache", config_, 0);
    TextureId fromCache = again.add(image);
    EXPECT_EQ(cachedFiles(), 2u);
    EXPECT_EQ(again.fingerprint(fromCache), textures.fingerprint(held));
    double worst = 0;
    for (uint32_t i = 0; i < 500; ++i) {
        float u = bitsToUnitFloat(hashValues({7, i})), v = bitsToUnitFloat(hashValues({8, i}));
        float ours[4], theirs[4];
        textures.lookup(held, {u, v}, 1e-5f, ours, 4);
        again.lookup(fromCache, {u, v}, 1e-5f, theirs, 4);
        for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(ours[c] - theirs[c])));
    }
    EXPECT_LT(worst, 1e-6);
    EXPECT_NE(streamed, held);
}

TEST(ResidentTextureFromImage, LevelsHalveToOneTexelHoldingTheMean) {
    Image image = testImage(37, 23, 2, 9);
    double sum[2] = {0, 0};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 2; ++c) sum[c] += image.at(x, y)[c];
    ResidentTexture texture = ResidentTexture::fromImage(image);
    // 37 × 23, 18 × 11, 9 × 5, 4 × 2, 2 × 1, 1 × 1.
    int64_t texels = 37 * 23 + 18 * 11 + 9 * 5 + 4 * 2 + 2 * 1 + 1;
    EXPECT_EQ(texture.bytes(), texels * 2 * int64_t(sizeof(float)));
    EXPECT_EQ(ResidentTexture::bytesFor(37, 23, 2), texture.bytes());
    float mean[2];
    texture.lookup({0.3f, 0.3f}, 1e3f, mean, 2);
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(mean[c], sum[c] / (37 * 23), 1e-5) << c;
    EXPECT_THROW(ResidentTexture::fromImage(Image()), std::invalid_argument);
}

}  // namespace
}  // namespace veduta
