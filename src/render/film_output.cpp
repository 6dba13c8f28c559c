#include "render/film_output.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <unistd.h>

namespace veduta {

namespace {

// The temporary keeps the target's extension: OpenImageIO picks the format by it.
std::filesystem::path temporaryName(const std::filesystem::path &file) {
    return file.parent_path() / fmt::format(".{}.tmp{}{}", file.stem().string(), getpid(), file.extension().string());
}

void writeImage(const std::filesystem::path &file, const OIIO::ImageSpec &spec, const void *pixels) {
    if (!file.parent_path().empty()) std::filesystem::create_directories(file.parent_path());
    std::filesystem::path tmp = temporaryName(file);
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write this image format: {}", file.string(), OIIO::geterror()));
    bool ok = out->open(tmp.string(), spec) && out->write_image(spec.format, pixels) && out->close();
    if (!ok) {
        std::string message = out->geterror();
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw std::runtime_error(fmt::format("{}: {}", file.string(), message));
    }
    std::error_code renameError;
    std::filesystem::rename(tmp, file, renameError);
    if (renameError) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw std::runtime_error(fmt::format("{}: cannot replace it: {}", file.string(), renameError.message()));
    }
}

}  // namespace

void prepareOutputFile(const std::filesystem::path &file) {
    std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw std::runtime_error(fmt::format("{}: cannot create its folder: {}", file.string(), error.message()));
    if (std::filesystem::is_directory(file)) throw std::runtime_error(fmt::format("{}: is a folder", file.string()));
    if (access(folder.c_str(), W_OK) != 0) {
        throw std::runtime_error(fmt::format("{}: its folder is not writable", file.string()));
    }
}

float linearToSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void writeExr(const Film &film, const std::filesystem::path &file) {
    OIIO::ImageSpec spec(film.width(), film.height(), 4, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A"};
    spec.alpha_channel = 3;
    spec.attribute("compression", "zip");
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("Software", "veduta");
    writeImage(file, spec, film.rgba());
}

void writePng(const Film &film, const std::filesystem::path &file) {
    OIIO::ImageSpec spec(film.width(), film.height(), 4, OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 3;
    spec.attribute("oiio:ColorSpace", "sRGB");
    std::vector<uint8_t> pixels(film.pixels().size());
    for (size_t i = 0; i < pixels.size(); ++i) {
        float v = (i % 4 == 3) ? std::clamp(film.pixels()[i], 0.0f, 1.0f) : linearToSrgb(film.pixels()[i]);
        pixels[i] = uint8_t(std::lround(v * 255.0f));
    }
    writeImage(file, spec, pixels.data());
}

}  // namespace veduta
