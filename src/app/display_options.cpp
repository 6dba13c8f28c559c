#include "app/display_options.h"
#include "app/number_option.h"

#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.h"
#include "core/file_extension.h"
#include "io/output_files.h"

namespace veduta {

namespace {

std::string checkDisplayImageFile(const std::string &text) {
    std::string extension = lowercaseExtension(text);
    for (const char *known : {".png", ".jpg", ".jpeg", ".tif", ".tiff"}) {
        if (extension == known) return {};
    }
    return fmt::format("'{}' is not a .png, .jpg, .jpeg, .tif or .tiff file", text);
}

}  // namespace

void addDisplayOptions(CLI::App &command, DisplayImageOptions &options) {
    DisplaySettings &settings = options.settings;
    CLI::Option *image =
        command
            .add_option("--image", options.file, "Also write a display image (PNG, JPEG, TIFF) through an OCIO view")
            ->check(CLI::Validator(checkDisplayImageFile, "FILE.png|jpg|tif"));
    command.add_option("--display", settings.display, "OCIO display of --image [the config's default]")->needs(image);
    command.add_option("--view", settings.view, "OCIO view of --image [the display's default]")->needs(image);
    command.add_option("--look", settings.look, "OCIO looks of --image, separated by commas [none]")->needs(image);
    command.add_option("--exposure", settings.exposureStops, "Exposure of --image in stops, before the view [0]")
        ->check(finiteIn(-64, 64))
        ->needs(image);
    command.add_option("--ocio-config", settings.config, "OCIO config for --image [$OCIO, else veduta's own]")
        ->check(CLI::ExistingFile)
        ->needs(image);
}

void checkDisplayOptions(const DisplayImageOptions &options) {
    if (options.file.empty()) return;
    prepareOutputFile(options.file);
    try {
        imageLibrary().checkDisplaySettings(options.settings);
    } catch (const InputError &e) {
        // veduta's own config once called its ACES view "Filmic", which Blender's Filmic it never was.
        const char *ocio = std::getenv("OCIO");
        bool builtIn = options.settings.config.empty() && (!ocio || !*ocio);
        if (!builtIn || options.settings.view != "Filmic") throw;
        throw InputError(e.loc(),
                         e.message() +
                             " (veduta's ACES 1.0 output transform, once called 'Filmic', is now the view "
                             "'ACES 1.0 - SDR Video': it never was Blender's Filmic, which --ocio-config "
                             "with Blender's config.ocio gives)");
    }
}

void writeDisplayImage(const RgbaImage &film, const DisplayImageOptions &options) {
    if (options.file.empty()) return;
    imageLibrary().writeDisplayImage(options.file, filmImage(film), options.settings);
}

Image filmImage(const RgbaImage &film) {
    Image image(film.width(), film.height(), 4);
    image.pixels = film.pixels();
    return image;
}

}  // namespace veduta
