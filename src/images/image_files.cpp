#include "images/image_files.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/input_file.h"

namespace veduta {

namespace {

// Alpha stays as the file stores it: OpenImageIO would otherwise premultiply the colour of
// formats with unassociated alpha (PNG) on reading and divide it on writing.
OIIO::ImageSpec keepAlpha(OIIO::ImageSpec spec) {
    spec.attribute("oiio:UnassociatedAlpha", 1);
    return spec;
}

// The most values (pixels × channels) an image may hold: 16 GiB of float.
constexpr uint64_t kMaxImageValues = uint64_t(1) << 32;

std::unique_ptr<OIIO::ImageInput> openImage(const std::filesystem::path &file) {
    checkInputFile(file);
    const OIIO::ImageSpec hints = keepAlpha(OIIO::ImageSpec());
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(file.string(), &hints);
    if (!input) throw InputError(FileLoc{file.string()}, OIIO::geterror());
    const OIIO::ImageSpec &spec = input->spec();
    if (spec.deep) throw InputError(FileLoc{file.string()}, "deep images are not supported");
    // Checked before the pixels are allocated: a header may claim any size.
    uint64_t values =
        uint64_t(std::max(spec.width, 0)) * uint64_t(std::max(spec.height, 0)) * uint64_t(std::max(spec.nchannels, 0));
    if (values > kMaxImageValues)
        throw InputError(FileLoc{file.string()},
                         fmt::format("is {} × {} pixels of {} channels; veduta reads images of up to {} values",
                                     spec.width, spec.height, spec.nchannels, kMaxImageValues));
    return input;
}

std::string knownSpace(const std::filesystem::path &file, const std::string &name, const ColorConfig &config) {
    if (auto found = config.find(name)) return *found;
    throw InputError(FileLoc{file.string()},
                     fmt::format("unknown colour space '{}' (the colour configuration has: {})", name, config.names()));
}

}  // namespace

OIIO::ImageSpec readImageSpec(const std::filesystem::path &file) { return openImage(file)->spec(); }

std::string fileColorSpace(const std::filesystem::path &file, const OIIO::ImageSpec &spec, const std::string &requested,
                           const ColorConfig &config) {
    if (!requested.empty()) return knownSpace(file, requested, config);
    if (auto declared = config.find(spec.get_string_attribute("oiio:ColorSpace"))) return *declared;
    bool isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
        spec.format.basetype == OIIO::TypeDesc::DOUBLE;
    return isFloat ? config.linear() : knownSpace(file, "sRGB", config);
}

Image readImageFile(const std::filesystem::path &file, const std::string &colorSpace, const ColorConfig &config) {
    std::unique_ptr<OIIO::ImageInput> input = openImage(file);
    const OIIO::ImageSpec &spec = input->spec();
    std::string space = fileColorSpace(file, spec, colorSpace, config);
    Image image(spec.width, spec.height, spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, image.pixels.data())) {
        throw InputError(FileLoc{file.string()}, input->geterror());
    }
    config.toLinear(image, space);
    return image;
}

void writeImageFile(const std::filesystem::path &file, const Image &image, const ColorConfig &config) {
    std::string extension = lowercaseExtension(file);
    bool keepsFloat = extension == ".exr" || extension == ".hdr";
    Image encoded = image;
    std::string space = keepsFloat ? config.linear() : knownSpace(file, "sRGB", config);
    config.fromLinear(encoded, space);
    const OIIO::TypeDesc format = keepsFloat ? OIIO::TypeFloat : OIIO::TypeUInt8;
    OIIO::ImageSpec spec(image.width, image.height, image.channels, format);
    spec.attribute("oiio:ColorSpace", space);
    if (extension == ".exr") spec.attribute("compression", "zip");
    writeEncodedImage(file, encoded, spec);
}

void writeEncodedImage(const std::filesystem::path &file, const Image &encoded, OIIO::ImageSpec spec) {
    spec = keepAlpha(std::move(spec));
    writeFileAtomically(file, [&](const std::filesystem::path &temporary) {
        std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(temporary.string());
        if (!output) throw std::runtime_error(fmt::format("{}: {}", file.string(), OIIO::geterror()));
        // Some of OpenImageIO's writers miss a failed write (PNG) or end the process on one
        // (libjpeg exits): formats that can are encoded in memory and written here, checked.
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        bool inMemory = output->supports("ioproxy") && output->set_ioproxy(&memory);
        bool written = output->open(temporary.string(), spec) &&
            output->write_image(OIIO::TypeFloat, encoded.pixels.data()) && output->close();
        if (!written) throw std::runtime_error(fmt::format("{}: {}", file.string(), output->geterror()));
        if (inMemory) writeWholeFile(temporary, bytes.data(), bytes.size(), file);
    });
}

}  // namespace veduta
