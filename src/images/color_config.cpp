#include "images/color_config.h"

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"

namespace veduta {

namespace OCIO = OCIO_NAMESPACE;

namespace {

OCIO::ConstConfigRcPtr readConfig(const std::string &file) {
    try {
        if (!file.empty()) return OCIO::Config::CreateFromFile(file.c_str());
        std::istringstream text(kVedutaOcioConfig);
        return OCIO::Config::CreateFromStream(text);
    } catch (const OCIO::Exception &e) {
        throw std::runtime_error(fmt::format("cannot read the colour configuration {}: {}",
                                             file.empty() ? kBuiltInConfigName : file, e.what()));
    }
}

}  // namespace

// One- and two-channel images go through as grey, whose conversion keeps grey.
void applyToColor(const OCIO::ConstCPUProcessorRcPtr &processor, Image &image) {
    const size_t pixels = size_t(image.width) * size_t(image.height);
    if (image.channels >= 3) {
        const ptrdiff_t stride = ptrdiff_t(image.channels * sizeof(float));
        OCIO::PackedImageDesc desc(image.pixels.data(), image.width, image.height, 3, OCIO::BIT_DEPTH_F32,
                                   sizeof(float), stride, stride * image.width);
        processor->apply(desc);
        return;
    }
    std::vector<float> rgb(pixels * 3);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = image.pixels[p * size_t(image.channels)];
    }
    OCIO::PackedImageDesc desc(rgb.data(), image.width, image.height, 3);
    processor->apply(desc);
    for (size_t p = 0; p < pixels; ++p) image.pixels[p * size_t(image.channels)] = rgb[p * 3];
}

std::shared_ptr<const ColorConfig> ColorConfig::load() {
    const char *variable = std::getenv("OCIO");
    std::string file = variable ? variable : "";
    return std::make_shared<const ColorConfig>(readConfig(file), file.empty() ? kBuiltInConfigName : file);
}

std::shared_ptr<const ColorConfig> ColorConfig::loadFile(const std::filesystem::path &file) {
    OCIO::ConstConfigRcPtr config;
    try {
        config = OCIO::Config::CreateFromFile(file.c_str());
        config->validate();
    } catch (const OCIO::Exception &e) {
        throw InputError(FileLoc{file.string()}, fmt::format("not a usable colour configuration: {}", e.what()));
    }
    if (!config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)) {
        throw InputError(FileLoc{file.string()}, "the colour configuration has no scene_linear role");
    }
    return std::make_shared<const ColorConfig>(config, file.string());
}

ColorConfig::ColorConfig(OCIO::ConstConfigRcPtr config, std::string source) :
    config_(std::move(config)), source_(std::move(source)) {
    OCIO::ConstColorSpaceRcPtr linear = config_->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
    if (!linear) throw std::runtime_error("the colour configuration has no scene_linear role");
    linear_ = linear->getName();
}

std::optional<std::string> ColorConfig::find(const std::string &name) const {
    OCIO::ConstColorSpaceRcPtr space = config_->getColorSpace(name.c_str());
    if (!space) return std::nullopt;
    return std::string(space->getName());
}

std::string ColorConfig::names() const {
    std::vector<std::string> list;
    for (int i = 0; i < config_->getNumColorSpaces(); ++i) list.emplace_back(config_->getColorSpaceNameByIndex(i));
    return fmt::format("{}", fmt::join(list, ", "));
}

void ColorConfig::toLinear(Image &image, const std::string &colorSpace) const { convert(image, colorSpace, linear_); }

void ColorConfig::fromLinear(Image &image, const std::string &colorSpace) const { convert(image, linear_, colorSpace); }

void ColorConfig::convert(Image &image, const std::string &from, const std::string &to) const {
    OCIO::ConstProcessorRcPtr processor = config_->getProcessor(from.c_str(), to.c_str());
    if (processor->isNoOp()) return;
    applyToColor(processor->getDefaultCPUProcessor(), image);
}

}  // namespace veduta
