// Display images: scene-linear pixels through an OpenColorIO display and view, written as PNG,
// JPEG or TIFF with the choice in the metadata (src/images/display_images.*).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>

#include "core/error.h"
#include "images/color_config.h"
#include "images/display_images.h"
#include "images/oiio_image_library.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

// A second config, as users give one by path: its own display and views.
const std::filesystem::path kOtherConfig = test::testData() / "gamma22.ocio";

class DisplayImageTest : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::path(testing::TempDir()) / fmt::format("veduta_display_{}", getpid());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // A one-row RGBA image of grey values, alpha 1.
    static Image greys(const std::vector<float> &values) {
        Image image(int(values.size()), 1, 4);
        for (int x = 0; x < image.width; ++x) {
            float *p = image.at(x, 0);
            p[0] = p[1] = p[2] = values[size_t(x)];
            p[3] = 1.0f;
        }
        return image;
    }

    // The samples of the file's first channel as stored, scaled to 0..255.
    static std::vector<int> storedRed(const std::filesystem::path &file) {
        OIIO::ImageSpec asStored;
        asStored.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::ImageBuf stored(file.string(), 0, 0, nullptr, &asStored);
        std::vector<float> values(size_t(stored.spec().image_pixels()) * size_t(stored.nchannels()));
        EXPECT_TRUE(stored.get_pixels(stored.roi(), OIIO::TypeFloat, values.data())) << stored.geterror();
        std::vector<int> red;
        for (size_t i = 0; i < values.size(); i += size_t(stored.nchannels())) {
            red.push_back(int(std::lround(values[i] * 255.0f)));
        }
        return red;
    }

    DisplayChoice choose(const DisplaySettings &settings) { return chooseDisplay(settings, ColorConfig::load()); }

    std::filesystem::path dir_;
    std::unique_ptr<ImageLibrary> library_ = makeOiioImageLibrary();
};

TEST_F(DisplayImageTest, DefaultIsTheStandardViewOfSrgb) {
    DisplayChoice choice = choose({});
    EXPECT_EQ(choice.display, "sRGB");
    EXPECT_EQ(choice.view, "Standard");
    library_->writeDisplayImage(dir_ / "half.png", greys({0.5f, 0.0f, 1.0f}), {});
    EXPECT_EQ(storedRed(dir_ / "half.png"), (std::vector<int>{188, 0, 255}));
}

// veduta's filmic view: the ACES 1.0 output transform, under the ACES studio config's name.
constexpr const char *kAcesView = "ACES 1.0 - SDR Video";

TEST_F(DisplayImageTest, AcesViewCompressesWhatStandardClips) {
    const std::vector<float> bright = {0.18f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
    DisplaySettings settings;
    library_->writeDisplayImage(dir_ / "standard.png", greys(bright), settings);
    settings.view = kAcesView;
    library_->writeDisplayImage(dir_ / "filmic.png", greys(bright), settings);
    std::vector<int> standard = storedRed(dir_ / "standard.png");
    std::vector<int> filmic = storedRed(dir_ / "filmic.png");
    std::printf("linear 0.18 1 2 4 8 16 -> Standard %d %d %d %d %d %d, ACES %d %d %d %d %d %d\n", standard[0],
                standard[1], standard[2], standard[3], standard[4], standard[5], filmic[0], filmic[1], filmic[2],
                filmic[3], filmic[4], filmic[5]);
    EXPECT_EQ(std::vector<int>(standard.begin() + 1, standard.end()), std::vector<int>(5, 255));
    // ACES' tone curve: mid grey darker than Standard's, every stop up to 8 still distinct
    // below white, and white reached only about 16 (100 nits for scene value ≈ 16).
    EXPECT_LT(filmic[0], standard[0]);
    for (size_t i = 1; i + 1 < filmic.size(); ++i) EXPECT_LT(filmic[i], filmic[i + 1]) << i;
    EXPECT_LT(filmic[4], 255);
    EXPECT_GE(filmic[5], 254);
}

TEST_F(DisplayImageTest, ExposureOneStopIsLightDoubled) {
    for (const char *view : {"Standard", kAcesView}) {
        DisplaySettings settings;
        settings.view = view;
        Image doubled = toDisplay(greys({0.02f, 0.2f, 0.9f}), choose(settings));
        settings.exposureStops = 1.0f;
        Image exposed = toDisplay(greys({0.01f, 0.1f, 0.45f}), choose(settings));
        for (size_t i = 0; i < doubled.pixels.size(); ++i) {
            EXPECT_NEAR(exposed.pixels[i], doubled.pixels[i], 1e-5f) << view << " sample " << i;
        }
    }
}

TEST_F(DisplayImageTest, PngJpegAndTiffRecordTheView) {
    DisplaySettings settings;
    settings.view = kAcesView;
    settings.exposureStops = 0.5f;
    Image image = greys({0.1f, 0.5f});
    image.pixels[3] = 0.5f;  // alpha, kept as it is where the format has it
    for (const char *name : {"out.png", "out.jpg", "out.tif"}) {
        library_->writeDisplayImage(dir_ / name, image, settings);
        std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open((dir_ / name).string());
        ASSERT_TRUE(input) << name << ": " << OIIO::geterror();
        const OIIO::ImageSpec &spec = input->spec();
        EXPECT_EQ(spec.width, 2) << name;
        EXPECT_NE(spec.get_string_attribute("ImageDescription").find("view 'ACES 1.0 - SDR Video'"), std::string::npos)
            << name << ": " << spec.get_string_attribute("ImageDescription");
        EXPECT_NE(spec.get_string_attribute("ImageDescription").find("exposure +0.5 stops"), std::string::npos) << name;
    }
    EXPECT_EQ(OIIO::ImageInput::open((dir_ / "out.tif").string())->spec().format, OIIO::TypeUInt16);
    EXPECT_EQ(OIIO::ImageInput::open((dir_ / "out.jpg").string())->spec().nchannels, 3);
    std::unique_ptr<OIIO::ImageInput> png = OIIO::ImageInput::open((dir_ / "out.png").string());
    EXPECT_EQ(png->spec().nchannels, 4);
    EXPECT_EQ(png->spec().get_string_attribute("ocioview"), kAcesView);
    EXPECT_EQ(png->spec().get_string_attribute("ociodisplay"), "sRGB");
    EXPECT_EQ(png->spec().get_string_attribute("oiio:ColorSpace"), "ACES 1.0 - SDR Video sRGB");
}

TEST_F(DisplayImageTest, AnotherConfigByPath) {
    DisplaySettings settings;
    settings.config = kOtherConfig;
    DisplayChoice choice = choose(settings);
    EXPECT_EQ(choice.display, "Rec709");
    EXPECT_EQ(choice.view, "Gamma2.2");
    library_->writeDisplayImage(dir_ / "g22.png", greys({0.5f}), settings);
    EXPECT_EQ(storedRed(dir_ / "g22.png"), std::vector<int>{int(std::lround(std::pow(0.5, 1 / 2.2) * 255))});
    settings.view = "Raw";
    library_->writeDisplayImage(dir_ / "raw.png", greys({0.5f}), settings);
    EXPECT_EQ(storedRed(dir_ / "raw.png"), std::vector<int>{128});
}

TEST_F(DisplayImageTest, BlendersConfigFilmic) {
    const std::filesystem::path blender = "/usr/share/blender/datafiles/colormanagement/config.ocio";
    if (!std::filesystem::exists(blender)) GTEST_SKIP() << blender << " is absent (Debian: blender-data)";
    DisplaySettings settings;
    settings.config = blender;
    settings.display = "sRGB";
    settings.view = "Filmic";
    library_->writeDisplayImage(dir_ / "blender.png", greys({0.18f, 8.0f, 64.0f}), settings);
    std::vector<int> red = storedRed(dir_ / "blender.png");
    // Blender's Filmic reaches white only at 0.18 · 2^6.5 ≈ 16.3: a stop below it is still grey.
    EXPECT_LT(red[0], red[1]);
    EXPECT_LT(red[1], 255);
    EXPECT_EQ(red[2], 255);
}

DisplaySettings named(const std::string &display, const std::string &view, const std::string &look = "",
                      const std::filesystem::path &config = {}) {
    DisplaySettings settings;
    settings.config = config;
    settings.display = display;
    settings.view = view;
    settings.look = look;
    return settings;
}

TEST_F(DisplayImageTest, UnknownNamesListTheValidOnes) {
    auto writing = [&](DisplaySettings settings) {
        return test::inputErrorOf([&] { library_->writeDisplayImage(dir_ / "bad.png", greys({0.5f}), settings); });
    };
    EXPECT_EQ(writing(named("sRBG", "")), "veduta.ocio (built in): unknown display 'sRBG'; displays: sRGB");
    EXPECT_EQ(writing(named("", "Filmc")),
              "veduta.ocio (built in): unknown view 'Filmc' for display 'sRGB'; views: "
              "Standard, ACES 1.0 - SDR Video, Raw");
    // Blender's Filmic is a LUT file veduta does not ship; no view takes its name.
    EXPECT_EQ(writing(named("", "Filmic")),
              "veduta.ocio (built in): unknown view 'Filmic' for display 'sRGB'; views: "
              "Standard, ACES 1.0 - SDR Video, Raw");
    EXPECT_EQ(writing(named("", "", "Filmic, Punchy")),
              "veduta.ocio (built in): unknown look 'Filmic'; looks: Gamut Compression, Blue Light Fix");
    std::filesystem::path other = kOtherConfig;
    EXPECT_EQ(writing(named("", "Filmic", "", other)),
              fmt::format("{}: unknown view 'Filmic' for display 'Rec709'; views: Gamma2.2, Raw", other.string()));
    EXPECT_EQ(writing(named("", "", "Punchy", other)),
              fmt::format("{}: unknown look 'Punchy'; looks: none", other.string()));
    EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.png"));
    EXPECT_NE(test::inputErrorOf([&] { library_->checkDisplaySettings(named("", "", "", dir_ / "missing.ocio")); }),
              "no error");
    EXPECT_EQ(test::inputErrorOf([&] { library_->checkDisplaySettings(named("", kAcesView, "+Blue Light Fix")); }),
              "no error");
}

TEST_F(DisplayImageTest, LooksChangeTheImage) {
    Image blue(1, 1, 4);
    blue.pixels = {0.0f, 0.0f, 4.0f, 1.0f};
    DisplaySettings settings;
    settings.view = kAcesView;
    Image plain = toDisplay(blue, choose(settings));
    settings.look = "Blue Light Fix";
    Image fixed = toDisplay(blue, choose(settings));
    std::printf("linear (0, 0, 4) through ACES: %g %g %g, with Blue Light Fix: %g %g %g\n", plain.pixels[0],
                plain.pixels[1], plain.pixels[2], fixed.pixels[0], fixed.pixels[1], fixed.pixels[2]);
    EXPECT_GT(std::abs(fixed.pixels[0] - plain.pixels[0]) + std::abs(fixed.pixels[1] - plain.pixels[1]), 0.01f);
}

TEST_F(DisplayImageTest, UnwritableFolderLeavesNothing) {
    if (geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
    std::filesystem::path folder = dir_ / "locked";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "old.png") << "the older image";
    chmod(folder.c_str(), 0555);
    EXPECT_THROW(library_->writeDisplayImage(folder / "old.png", greys({0.5f}), {}), std::runtime_error);
    chmod(folder.c_str(), 0755);
    std::vector<std::filesystem::path> left;
    for (const auto &entry : std::filesystem::directory_iterator(folder)) left.push_back(entry.path().filename());
    EXPECT_EQ(left, std::vector<std::filesystem::path>{"old.png"});
    EXPECT_EQ(std::filesystem::file_size(folder / "old.png"), std::string("the older image").size());
}

// Files may grow to `bytes` while alive, and writes beyond fail (EFBIG) as on a full disk.
class ScopedFileSizeLimit {
  public:
    explicit ScopedFileSizeLimit(rlim_t bytes) {
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        getrlimit(RLIMIT_FSIZE, &old_);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~ScopedFileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }
    ScopedFileSizeLimit(const ScopedFileSizeLimit &) = delete;
    ScopedFileSizeLimit &operator=(const ScopedFileSizeLimit &) = delete;

  private:
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

TEST_F(DisplayImageTest, WriteFailingPartWayKeepsTheOlderFile) {
    Image noise(256, 256, 4);
    for (size_t i = 0; i < noise.pixels.size(); ++i) noise.pixels[i] = float((i * 2654435761u) % 1000) / 1000.0f;
    std::ofstream(dir_ / "old.png") << "the older image";
    for (const char *name : {"old.png", "new.jpg", "new.tif"}) {
        std::string message;
        {
            ScopedFileSizeLimit limit(4096);
            try {
                library_->writeDisplayImage(dir_ / name, noise, {});
            } catch (const std::runtime_error &e) {
                message = e.what();
            }
        }
        std::printf("%s: %s\n", name, message.c_str());
        EXPECT_NE(message.find((dir_ / name).string()), std::string::npos) << name << ": " << message;
    }
    std::vector<std::filesystem::path> left;
    for (const auto &entry : std::filesystem::directory_iterator(dir_)) left.push_back(entry.path().filename());
    EXPECT_EQ(left, std::vector<std::filesystem::path>{"old.png"});
    EXPECT_EQ(std::filesystem::file_size(dir_ / "old.png"), std::string("the older image").size());
}

}  // namespace
}  // namespace veduta
