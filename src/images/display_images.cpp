#include "images/display_images.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"
#include "core/file_extension.h"
#include "images/image_files.h"

namespace veduta {

namespace OCIO = OCIO_NAMESPACE;

namespace {

std::string listed(const std::vector<std::string> &names) {
    return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

std::vector<std::string> displayNames(const OCIO::Config &config) {
    std::vector<std::string> names;
    for (int i = 0; i < config.getNumDisplays(); ++i) names.emplace_back(config.getDisplay(i));
    return names;
}

std::vector<std::string> viewNames(const OCIO::Config &config, const std::string &display) {
    std::vector<std::string> names;
    for (int i = 0; i < config.getNumViews(display.c_str()); ++i) {
        names.emplace_back(config.getView(display.c_str(), i));
    }
    return names;
}

std::vector<std::string> lookNames(const OCIO::Config &config) {
    std::vector<std::string> names;
    for (int i = 0; i < config.getNumLooks(); ++i) names.emplace_back(config.getLookNameByIndex(i));
    return names;
}

// The names in an OCIO looks string ("a, +b, -c": a sign asks for the look or its inverse).
std::vector<std::string> looksIn(const std::string &looks) {
    std::vector<std::string> names;
    size_t start = 0;
    while (start <= looks.size()) {
        size_t end = std::min(looks.find(',', start), looks.size());
        std::string name = looks.substr(start, end - start);
        name.erase(0, name.find_first_not_of(" \t+-"));
        name.erase(name.find_last_not_of(" \t") + 1);
        names.push_back(name);
        start = end + 1;
    }
    return names;
}

// `asked`, or `fallback` when nothing was asked, if it is one of `names`. `what` names the kind
// ("display") and `of` what it belongs to (" for display 'sRGB'"), for the message.
std::string chooseName(const std::string &asked, const std::string &fallback, const std::vector<std::string> &names,
                       const std::string &what, const std::string &of, const FileLoc &where) {
    std::string name = asked.empty() ? fallback : asked;
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        throw InputError(where, fmt::format("unknown {} '{}'{}; {}s: {}", what, name, of, what, listed(names)));
    }
    return name;
}

void checkLooks(const std::string &looks, const OCIO::Config &config, const FileLoc &where) {
    if (looks.empty()) return;
    for (const std::string &name : looksIn(looks)) {
        if (!config.getLook(name.c_str())) {
            throw InputError(where, fmt::format("unknown look '{}'; looks: {}", name, listed(lookNames(config))));
        }
    }
}

OCIO::ConstProcessorRcPtr displayProcessor(const DisplayChoice &choice) {
    const ColorConfig &config = *choice.config;
    OCIO::DisplayViewTransformRcPtr view = OCIO::DisplayViewTransform::Create();
    view->setSrc(config.linear().c_str());
    view->setDisplay(choice.display.c_str());
    view->setView(choice.view.c_str());
    OCIO::LegacyViewingPipelineRcPtr pipeline = OCIO::LegacyViewingPipeline::Create();
    pipeline->setDisplayViewTransform(view);
    if (!choice.look.empty()) {
        pipeline->setLooksOverrideEnabled(true);
        pipeline->setLooksOverride(choice.look.c_str());
    }
    if (choice.exposureStops != 0.0f) {
        // Blender's exposure: a scale of scene-linear light, before the view's tone curve.
        double gain = std::exp2(double(choice.exposureStops));
        const double matrix[16] = {gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, 1};
        OCIO::MatrixTransformRcPtr exposure = OCIO::MatrixTransform::Create();
        exposure->setMatrix(matrix);
        pipeline->setLinearCC(exposure);
    }
    try {
        return pipeline->getProcessor(config.ocio(), config.ocio()->getCurrentContext());
    } catch (const OCIO::Exception &e) {
        throw InputError(
            FileLoc{config.source()},
            fmt::format("cannot build the view '{}' of display '{}': {}", choice.view, choice.display, e.what()));
    }
}

std::string describe(const DisplayChoice &choice) {
    return fmt::format("OCIO display '{}', view '{}', look '{}', exposure {:+g} stops, config {}", choice.display,
                       choice.view, choice.look.empty() ? "None" : choice.look, choice.exposureStops,
                       choice.config->source());
}

// JPEG stores no alpha: its files get the colour channels only.
Image colourOnly(const Image &image) {
    if (image.channels <= 3) return image;
    Image colour(image.width, image.height, 3);
    for (size_t p = 0; p < size_t(image.width) * size_t(image.height); ++p) {
        std::copy_n(&image.pixels[p * size_t(image.channels)], 3, &colour.pixels[p * 3]);
    }
    return colour;
}

}  // namespace

DisplayChoice chooseDisplay(const DisplaySettings &settings, std::shared_ptr<const ColorConfig> fallback) {
    DisplayChoice choice;
    choice.config = settings.config.empty() ? std::move(fallback) : ColorConfig::loadFile(settings.config);
    const OCIO::Config &config = *choice.config->ocio();
    const FileLoc where{choice.config->source()};
    choice.display =
        chooseName(settings.display, config.getDefaultDisplay(), displayNames(config), "display", "", where);
    choice.view =
        chooseName(settings.view, config.getDefaultView(choice.display.c_str()), viewNames(config, choice.display),
                   "view", fmt::format(" for display '{}'", choice.display), where);
    checkLooks(settings.look, config, where);
    choice.look = settings.look;
    choice.exposureStops = settings.exposureStops;
    return choice;
}

Image toDisplay(const Image &linear, const DisplayChoice &choice) {
    Image display = linear;
    applyToColor(displayProcessor(choice)->getDefaultCPUProcessor(), display);
    return display;
}

void writeDisplayImageFile(const std::filesystem::path &file, const Image &linear, const DisplayChoice &choice) {
    const std::string extension = lowercaseExtension(file);
    const bool jpeg = extension == ".jpg" || extension == ".jpeg";
    const bool tiff = extension == ".tif" || extension == ".tiff";
    if (!jpeg && !tiff && extension != ".png") {
        throw InputError(FileLoc{file.string()},
                         "display images are PNG, JPEG or TIFF (.png, .jpg, .jpeg, .tif, .tiff)");
    }
    Image display = toDisplay(jpeg ? colourOnly(linear) : linear, choice);
    OIIO::ImageSpec spec(display.width, display.height, display.channels, tiff ? OIIO::TypeUInt16 : OIIO::TypeUInt8);
    const OCIO::Config &config = *choice.config->ocio();
    spec.attribute("oiio:ColorSpace", config.getDisplayViewColorSpaceName(choice.display.c_str(), choice.view.c_str()));
    spec.attribute("ocioconfig", choice.config->source());
    spec.attribute("ociodisplay", choice.display);
    spec.attribute("ocioview", choice.view);
    spec.attribute("ociolook", choice.look.empty() ? "None" : choice.look);
    spec.attribute("ocioexposure", choice.exposureStops);
    spec.attribute("ImageDescription", describe(choice));
    spec.attribute("Software", "veduta");
    writeEncodedImage(file, display, spec);
}

}  // namespace veduta
