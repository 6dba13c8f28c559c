#include "images/oiio_image_library.h"

#include "images/color_config.h"
#include "images/display_images.h"
#include "images/image_files.h"
#include "images/oiio_textures.h"

namespace veduta {

namespace {

class OiioImageLibrary final : public ImageLibrary {
  public:
    OiioImageLibrary() : config_(ColorConfig::load()) {}

    Image read(const std::filesystem::path &file, const std::string &colorSpace) override {
        return readImageFile(file, colorSpace, *config_);
    }
    void write(const std::filesystem::path &file, const Image &image) override {
        writeImageFile(file, image, *config_);
    }
    void writeDisplayImage(const std::filesystem::path &file, const Image &linear,
                           const DisplaySettings &settings) override {
        writeDisplayImageFile(file, linear, chooseDisplay(settings, config_));
    }
    void checkDisplaySettings(const DisplaySettings &settings) override { chooseDisplay(settings, config_); }
    std::shared_ptr<Textures> makeTextures(const std::filesystem::path &cacheDirectory) override {
        return std::make_shared<OiioTextures>(cacheDirectory, config_);
    }

  private:
    std::shared_ptr<const ColorConfig> config_;
};

}  // namespace

std::unique_ptr<ImageLibrary> makeOiioImageLibrary() { return std::make_unique<OiioImageLibrary>(); }

}  // namespace veduta
