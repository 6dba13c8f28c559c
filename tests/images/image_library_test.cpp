#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "core/hash.h"
#include "images/color_config.h"
#include "images/oiio_image_library.h"
#include "io/image_library.h"
#include "test_paths.h"

namespace veduta {
namespace {

// The sRGB decoding (IEC 61966-2-1), written out to check OpenColorIO's against.
double srgbToLinear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Sets an environment variable for one scope and restores the old value after it.
class ScopedEnv {
  public:
    ScopedEnv(const char *name, const std::optional<std::string> &value) : name_(name) {
        if (const char *old = std::getenv(name)) old_ = old;
        set(value);
    }
    ~ScopedEnv() { set(old_); }
    ScopedEnv(const ScopedEnv &) = delete;
    ScopedEnv &operator=(const ScopedEnv &) = delete;

  private:
    void set(const std::optional<std::string> &value) {
        if (value) {
            setenv(name_, value->c_str(), 1);
        } else {
            unsetenv(name_);
        }
    }
    const char *name_;
    std::optional<std::string> old_;
};

class ImageLibraryTest : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::path(testing::TempDir()) / fmt::format("veduta_image_library_{}", getpid());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // An 8-bit file holding exactly `values` (width · height · channels), no conversion.
    std::filesystem::path write8Bit(const std::string &name, int width, int height, int channels,
                                    const std::vector<unsigned char> &values) {
        std::filesystem::path file = dir_ / name;
        OIIO::ImageBuf image(OIIO::ImageSpec(width, height, channels, OIIO::TypeUInt8), (void *)values.data());
        EXPECT_TRUE(image.write(file.string())) << image.geterror();
        return file;
    }

    std::filesystem::path dir_;
    std::unique_ptr<ImageLibrary> library_ = makeOiioImageLibrary();
};

TEST_F(ImageLibraryTest, ExrRoundTripIsBitExact) {
    Image image(5, 3, 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = bitsToUnitFloat(mix32(uint32_t(i))) * 40000.0f - 100.0f;
    }
    image.pixels[7] = 1e-30f;
    library_->write(dir_ / "round.exr", image);
    Image read = library_->read(dir_ / "round.exr", "");
    EXPECT_EQ(read.width, 5);
    EXPECT_EQ(read.height, 3);
    EXPECT_EQ(read.channels, 4);
    EXPECT_EQ(read.pixels, image.pixels);
}

TEST_F(ImageLibraryTest, OneChannelStaysOneChannel) {
    Image grey(4, 2, 1);
    for (size_t i = 0; i < grey.pixels.size(); ++i) grey.pixels[i] = 0.125f * float(i);
    library_->write(dir_ / "grey.exr", grey);
    Image read = library_->read(dir_ / "grey.exr", "");
    EXPECT_EQ(read.channels, 1);
    EXPECT_EQ(read.pixels, grey.pixels);
}

TEST_F(ImageLibraryTest, PngRoundTripGoesThroughSrgb8Bit) {
    Image image(2, 1, 4);
    for (int x = 0; x < 2; ++x) {
        float *p = image.at(x, 0);
        p[0] = p[1] = p[2] = 0.5f;
        p[3] = 0.5f;  // alpha: stored linearly, not with the sRGB transfer
    }
    library_->write(dir_ / "half.png", image);

    OIIO::ImageSpec asStored;  // not premultiplied by alpha on reading
    asStored.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageBuf stored((dir_ / "half.png").string(), 0, 0, nullptr, &asStored);
    std::vector<unsigned char> bytes(8);
    ASSERT_TRUE(stored.get_pixels(stored.roi(), OIIO::TypeUInt8, bytes.data())) << stored.geterror();
    EXPECT_EQ(bytes, (std::vector<unsigned char>{188, 188, 188, 128, 188, 188, 188, 128}));

    Image read = library_->read(dir_ / "half.png", "");
    ASSERT_EQ(read.channels, 4);
    EXPECT_NEAR(read.at(1, 0)[0], srgbToLinear(188.0 / 255.0), 1e-6);
    EXPECT_NEAR(read.at(1, 0)[0], 0.5, 0.5 * 0.01);  // 8 bits near 0.5 are about 1 % apart
    EXPECT_EQ(read.at(1, 0)[3], 128.0f / 255.0f);
}

TEST_F(ImageLibraryTest, IntegerFilesAreSrgbUnlessToldOtherwise) {
    std::filesystem::path file = write8Bit("grey128.png", 1, 1, 3, {128, 128, 128});
    const float linear = library_->read(file, "sRGB").pixels[0];
    std::printf("8-bit 128 read as sRGB: %.7f (formula %.7f)\n", linear, srgbToLinear(128.0 / 255.0));
    EXPECT_NEAR(linear, 0.2158605, 1e-6);
    EXPECT_NEAR(linear, srgbToLinear(128.0 / 255.0), 1e-6);
    EXPECT_EQ(library_->read(file, "").pixels[0], linear);
    EXPECT_EQ(library_->read(file, "srgb").pixels[0], linear);
    for (const char *data : {"Non-Color", "raw"}) {
        Image read = library_->read(file, data);
        EXPECT_EQ(read.pixels, std::vector<float>(3, 128.0f / 255.0f)) << data;
    }
    EXPECT_EQ(library_->read(file, "Linear").pixels[0], 128.0f / 255.0f);
}

TEST_F(ImageLibraryTest, FloatFilesAreLinear) {
    Image image(1, 1, 3);
    image.pixels = {0.25f, 2.0f, 1000.0f};
    library_->write(dir_ / "light.hdr", image);
    Image read = library_->read(dir_ / "light.hdr", "");
    ASSERT_EQ(read.channels, 3);
    // RGBE keeps 8 bits of mantissa per channel, sharing the largest channel's exponent.
    EXPECT_NEAR(read.pixels[2], 1000.0f, 1000.0f / 256);
    EXPECT_NEAR(read.pixels[1], 2.0f, 1000.0f / 256);
}

TEST_F(ImageLibraryTest, UnknownColorSpaceIsAnInputErrorNamingIt) {
    std::filesystem::path file = write8Bit("grey.png", 1, 1, 3, {128, 128, 128});
    try {
        library_->read(file, "Filmic Wonder");
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string(), 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("'Filmic Wonder'"), std::string::npos) << e.what();
    }
}

TEST_F(ImageLibraryTest, MissingAndBrokenFilesAreInputErrorsStartingWithTheirName) {
    std::filesystem::path text = dir_ / "not_an_image.png";
    std::ofstream(text) << "this is not a PNG\n";
    for (const std::filesystem::path &file : {dir_ / "missing.png", text}) {
        try {
            library_->read(file, "");
            FAIL() << "no error for " << file;
        } catch (const InputError &e) {
            std::string message = e.what();
            std::printf("%s\n", message.c_str());
            EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
            EXPECT_GT(message.size(), file.string().size() + 2) << "OpenImageIO's reason is missing";
        }
        EXPECT_THROW(library_->makeTextures(dir_ / "cache")->add(file, ""), InputError);
    }
}

TEST_F(ImageLibraryTest, WriteFailureNamesTheFile) {
    Image image(1, 1, 3);
    EXPECT_THROW(library_->write(dir_ / "image.unknown-format", image), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(dir_ / "image.unknown-format"));
}

TEST(ColorConfig, EmbeddedConfigIsValid) {
    std::istringstream text(kVedutaOcioConfig);
    OCIO_NAMESPACE::ConstConfigRcPtr config = OCIO_NAMESPACE::Config::CreateFromStream(text);
    EXPECT_NO_THROW(config->validate());
    ColorConfig colors(config);
    EXPECT_EQ(colors.linear(), "Linear");
    for (auto [name, space] : std::vector<std::pair<std::string, std::string>>{{"linear", "Linear"},
                                                                               {"Linear Rec.709", "Linear"},
                                                                               {"srgb", "sRGB"},
                                                                               {"raw", "Non-Color"},
                                                                               {"Non-Color", "Non-Color"}}) {
        EXPECT_EQ(colors.find(name), space) << name;
    }
    EXPECT_EQ(colors.find("ACEScg"), std::nullopt);
}

TEST(ColorConfig, OciocheckAcceptsTheEmbeddedConfig) {
    if (std::system("command -v ociocheck >/dev/null 2>&1") != 0) GTEST_SKIP() << "ociocheck is not installed";
    std::filesystem::path file =
        std::filesystem::path(testing::TempDir()) / fmt::format("veduta_ocio_{}.ocio", getpid());
    std::ofstream(file) << kVedutaOcioConfig;
    int status = std::system(fmt::format("ociocheck --iconfig '{}' >/dev/null", file.string()).c_str());
    std::filesystem::remove(file);
    EXPECT_EQ(status, 0);
}

TEST_F(ImageLibraryTest, OcioEnvironmentVariableChoosesTheConfig) {
    std::filesystem::path configFile = dir_ / "doubled.ocio";
    std::ofstream(configFile) << kVedutaOcioConfig << R"(
  - !<ColorSpace>
    name: Doubled
    isdata: false
    to_scene_reference: !<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}
)";
    std::filesystem::path file = write8Bit("grey.png", 1, 1, 3, {128, 128, 128});
    {
        ScopedEnv ocio("OCIO", configFile.string());
        EXPECT_EQ(makeOiioImageLibrary()->read(file, "Doubled").pixels[0], 2.0f * 128.0f / 255.0f);
    }
    EXPECT_THROW(library_->read(file, "Doubled"), InputError);
    ScopedEnv missing("OCIO", (dir_ / "missing.ocio").string());
    EXPECT_THROW(makeOiioImageLibrary(), std::runtime_error);
}

// An 8x8 RGB checker of two colours, texel (0, 0) at the top left being `kFirst`.
constexpr unsigned char kFirst[3] = {200, 50, 10};
constexpr unsigned char kSecond[3] = {20, 100, 250};
constexpr int kCheckerSize = 8;

const unsigned char *checkerTexel(int x, int y) { return (x + y) % 2 == 0 ? kFirst : kSecond; }

// What a lookup of an 8-bit sRGB texel returns: linearised (textures are stored in float).
double textureValue(unsigned char encoded) { return srgbToLinear(encoded / 255.0); }

class TexturesTest : public ImageLibraryTest {
  protected:
    void SetUp() override {
        ImageLibraryTest::SetUp();
        std::vector<unsigned char> values;
        for (int y = 0; y < kCheckerSize; ++y) {
            for (int x = 0; x < kCheckerSize; ++x) {
                values.insert(values.end(), checkerTexel(x, y), checkerTexel(x, y) + 3);
            }
        }
        checker_ = write8Bit("checker.png", kCheckerSize, kCheckerSize, 3, values);
        textures_ = library_->makeTextures(cache());
        id_ = textures_->add(checker_, "");
    }

    std::filesystem::path cache() const { return dir_ / "cache"; }

    std::vector<std::filesystem::path> cachedFiles() const {
        std::vector<std::filesystem::path> files;
        for (const auto &entry : std::filesystem::directory_iterator(cache())) files.push_back(entry.path());
        return files;
    }

    std::vector<float> lookup(float u, float v, float footprint) const {
        std::vector<float> out(3, -1.0f);
        textures_->lookup(id_, Vec2f{u, v}, footprint, out.data(), 3);
        return out;
    }

    // The texel centre's coordinates, v up.
    static Vec2f centre(int x, int y) {
        return {(float(x) + 0.5f) / kCheckerSize, 1.0f - (float(y) + 0.5f) / kCheckerSize};
    }

    std::filesystem::path checker_;
    std::shared_ptr<Textures> textures_;
    TextureId id_ = kNoTexture;
};

TEST_F(TexturesTest, SameFileAndColorSpaceGiveTheSameId) {
    EXPECT_EQ(textures_->channels(id_), 3);
    EXPECT_EQ(textures_->add(checker_, ""), id_);
    EXPECT_EQ(textures_->add(checker_, "sRGB"), id_) << "the file's own colour space, named";
    EXPECT_EQ(textures_->add(dir_ / "." / "checker.png", "srgb"), id_);
    TextureId data = textures_->add(checker_, "Non-Color");
    EXPECT_NE(data, id_);
    EXPECT_EQ(cachedFiles().size(), 2u);
    float value = 0;
    Vec2f uv = centre(0, 0);
    textures_->lookup(data, uv, 1e-4f, &value, 1);
    EXPECT_NEAR(value, kFirst[0] / 255.0, 1e-7);
}

TEST_F(TexturesTest, ConvertedTextureIsCachedAndReused) {
    std::vector<std::filesystem::path> files = cachedFiles();
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].extension(), ".tx");
    struct stat before {};
    ASSERT_EQ(stat(files[0].c_str(), &before), 0);
    std::filesystem::file_time_type modified = std::filesystem::last_write_time(files[0]);

    std::shared_ptr<Textures> again = library_->makeTextures(cache());
    TextureId id = again->add(checker_, "");
    std::vector<float> first(3), second(3);
    textures_->lookup(id_, centre(3, 5), 1e-4f, first.data(), 3);
    again->lookup(id, centre(3, 5), 1e-4f, second.data(), 3);
    EXPECT_EQ(first, second);

    struct stat after {};
    ASSERT_EQ(stat(files[0].c_str(), &after), 0);
    EXPECT_EQ(after.st_ino, before.st_ino) << "the texture was written again";
    EXPECT_EQ(std::filesystem::last_write_time(files[0]), modified);
    EXPECT_EQ(cachedFiles(), files);
}

TEST_F(TexturesTest, ChangedFileIsConvertedAgain) {
    std::vector<unsigned char> white(kCheckerSize * kCheckerSize * 3, 255);
    std::filesystem::remove(checker_);
    write8Bit("checker.png", kCheckerSize, kCheckerSize, 3, white);
    std::filesystem::last_write_time(checker_, std::filesystem::last_write_time(checker_) + std::chrono::seconds(1));
    std::shared_ptr<Textures> fresh = library_->makeTextures(cache());
    float value = 0;
    fresh->lookup(fresh->add(checker_, ""), centre(0, 0), 1e-4f, &value, 1);
    EXPECT_EQ(value, 1.0f);
    EXPECT_EQ(cachedFiles().size(), 2u);
}

TEST_F(TexturesTest, TexelCentresWithATinyFootprintGiveTheTexel) {
    for (int y = 0; y < kCheckerSize; ++y) {
        for (int x = 0; x < kCheckerSize; ++x) {
            Vec2f uv = centre(x, y);
            std::vector<float> value = lookup(uv.x, uv.y, 1e-4f);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(value[c], textureValue(checkerTexel(x, y)[c]), 1e-6) << x << " " << y;
            }
        }
    }
}

TEST_F(TexturesTest, LargeFootprintGivesTheMean) {
    std::vector<float> value = lookup(0.3f, 0.6f, 2.0f);
    for (int c = 0; c < 3; ++c) {
        double mean = 0.5 * (srgbToLinear(kFirst[c] / 255.0) + srgbToLinear(kSecond[c] / 255.0));
        std::printf("channel %d: large-footprint lookup %.8f, mean %.8f\n", c, value[c], mean);
        // Three levels of float averages: a few float roundings.
        EXPECT_NEAR(value[c], mean, mean * 1e-6) << c;
    }
}

// Footprints of a whole period or more give the mean kept at add(), without OpenImageIO; just
// below that, OpenImageIO's own filtering is all but there already, on a texture whose
// coarser levels are not uniform (a ramp, unlike the checker).
TEST_F(TexturesTest, TheMeanTakesOverSmoothlyAtAWholePeriod) {
    std::vector<unsigned char> ramp;
    for (int y = 0; y < kCheckerSize; ++y)
        for (int x = 0; x < kCheckerSize; ++x)
            ramp.insert(ramp.end(), {static_cast<unsigned char>(x * 36), static_cast<unsigned char>(y * 36), 128});
    TextureId id = textures_->add(write8Bit("ramp.png", kCheckerSize, kCheckerSize, 3, ramp), "");
    auto at = [&](Vec2f uv, float footprint) {
        std::vector<float> out(3);
        textures_->lookup(id, uv, footprint, out.data(), 3);
        return out;
    };
    std::vector<float> mean = at({0.5f, 0.5f}, 1.0f);
    for (Vec2f uv : {Vec2f{0.1f, 0.2f}, Vec2f{0.9f, 0.6f}, Vec2f{-3.3f, 7.7f}}) {
        EXPECT_EQ(at(uv, 1.0f), mean);
        EXPECT_EQ(at(uv, 50.0f), mean);
        std::vector<float> below = at(uv, 0.999f), coarse = at(uv, 0.25f);
        for (int c = 0; c < 2; ++c) {
            EXPECT_NEAR(below[c], mean[c], 0.01 * mean[c]) << c;
            EXPECT_GT(std::abs(coarse[c] - mean[c]), 0.05 * mean[c]) << c << ": the ramp shows at a quarter";
        }
    }
}

TEST_F(TexturesTest, WrapsPeriodically) {
    for (float v : {0.1f, 0.37f, 0.8f}) {
        EXPECT_EQ(lookup(1.25f, v, 1e-4f), lookup(0.25f, v, 1e-4f)) << v;
        EXPECT_EQ(lookup(0.25f, v + 1.0f, 1e-4f), lookup(0.25f, v, 1e-4f)) << v;
        EXPECT_EQ(lookup(-0.75f, v, 1e-4f), lookup(0.25f, v, 1e-4f)) << v;
    }
}

TEST_F(TexturesTest, VGrowsUpwards) {
    // v = 0.99 lies 0.08 texels below the top edge: bilinear between the top row's centre
    // (0.42 texels away) and, wrapping, the bottom row's (0.58 away). v = 0.01 mirrors it.
    const float u = centre(0, 0).x;
    const double near = 0.5 + (1.0 - 0.99f) * kCheckerSize;  // weight of the nearer row
    std::vector<float> top = lookup(u, 0.99f, 1e-4f), bottom = lookup(u, 0.01f, 1e-4f);
    for (int c = 0; c < 3; ++c) {
        double topRow = textureValue(checkerTexel(0, 0)[c]);
        double bottomRow = textureValue(checkerTexel(0, kCheckerSize - 1)[c]);
        EXPECT_NEAR(top[c], near * topRow + (1 - near) * bottomRow, 1e-5) << c;
        EXPECT_NEAR(bottom[c], near * bottomRow + (1 - near) * topRow, 1e-5) << c;
    }
}

TEST_F(TexturesTest, ParallelLookupsEqualSerialOnes) {
    constexpr int kLookups = 20000;
    auto coordinates = [](int i) {
        return std::make_tuple(bitsToUnitFloat(hashValues({1, uint32_t(i)})) * 3.0f - 1.0f,
                               bitsToUnitFloat(hashValues({2, uint32_t(i)})) * 3.0f - 1.0f,
                               std::ldexp(bitsToUnitFloat(hashValues({3, uint32_t(i)})), -int(i % 12)));
    };
    std::vector<float> serial(kLookups * 3), parallel(kLookups * 3);
    for (int i = 0; i < kLookups; ++i) {
        auto [u, v, footprint] = coordinates(i);
        textures_->lookup(id_, Vec2f{u, v}, footprint, &serial[size_t(i) * 3], 3);
    }
    tbb::parallel_for(0, kLookups, [&](int i) {
        auto [u, v, footprint] = coordinates(i);
        textures_->lookup(id_, Vec2f{u, v}, footprint, &parallel[size_t(i) * 3], 3);
    });
    EXPECT_EQ(parallel, serial);
}

TEST(ImagePlugin, LoadsFromVedutaImagePlugin) {
    ScopedEnv plugin("VEDUTA_IMAGE_PLUGIN", test::imagePluginFile());
    EXPECT_EQ(imagePluginPath(), test::imagePluginFile());
    ImageLibrary &library = imageLibrary();
    EXPECT_EQ(&library, &imageLibrary()) << "loaded once";
    std::filesystem::path file =
        std::filesystem::path(testing::TempDir()) / fmt::format("veduta_plugin_{}.exr", getpid());
    Image image(2, 2, 3);
    image.pixels[4] = 3.5f;
    library.write(file, image);
    Image read = library.read(file, "");
    std::filesystem::remove(file);
    EXPECT_EQ(read.pixels, image.pixels);
}

TEST(ImagePlugin, DefaultPathIsBesideTheProgram) {
    ScopedEnv plugin("VEDUTA_IMAGE_PLUGIN", std::nullopt);
    EXPECT_EQ(imagePluginPath().filename(), "veduta-images.so");
    EXPECT_EQ(imagePluginPath().parent_path(), std::filesystem::read_symlink("/proc/self/exe").parent_path());
}

TEST(ImagePlugin, WrongPathGivesAClearError) {
    try {
        loadImageLibrary("/nonexistent/veduta-images.so");
        FAIL() << "no error";
    } catch (const std::runtime_error &e) {
        std::string message = e.what();
        std::printf("%s\n", message.c_str());
        EXPECT_NE(message.find("/nonexistent/veduta-images.so"), std::string::npos) << message;
        EXPECT_NE(message.find("VEDUTA_IMAGE_PLUGIN"), std::string::npos) << message;
    }
}

TEST(ImagePlugin, DefaultTextureCacheDirectory) {
    ScopedEnv home("HOME", "/home/someone");
    {
        ScopedEnv cache("VEDUTA_CACHE_DIR", "/tmp/veduta-cache");
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(defaultTextureCacheDirectory(), "/tmp/veduta-cache");
    }
    ScopedEnv cache("VEDUTA_CACHE_DIR", std::nullopt);
    {
        ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
        EXPECT_EQ(defaultTextureCacheDirectory(), "/xdg/veduta/textures");
    }
    ScopedEnv xdg("XDG_CACHE_HOME", std::nullopt);
    EXPECT_EQ(defaultTextureCacheDirectory(), "/home/someone/.cache/veduta/textures");
}

TEST_F(ImageLibraryTest, ReadsTheCityHdri) {
    std::filesystem::path file = test::sourceDir() / "../shared/data/hdri/city.exr";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not there";
    Image image = library_->read(file, "");
    EXPECT_EQ(image.width, 1024);
    EXPECT_EQ(image.height, 512);
    EXPECT_EQ(image.channels, 3);
    float brightest = *std::max_element(image.pixels.begin(), image.pixels.end());
    std::printf("city.exr: %dx%d, %d channels, max %.1f\n", image.width, image.height, image.channels, brightest);
    EXPECT_NEAR(brightest, 33952.0f, 1.0f);
}

}  // namespace
}  // namespace veduta
