#include "io/output_files.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <png.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "io/exr_file.h"

// Written with OpenEXR and libpng directly rather than through OpenImageIO: Debian's
// OpenImageIO loads some 260 shared libraries, which costs about 0.6 s at every start of a
// program linked to it, too much for `veduta preview`. OpenImageIO stays for reading images
// of any format (`veduta diff`), in a separate program.

namespace veduta {

void prepareOutputFile(const std::filesystem::path &file) {
    std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw std::runtime_error(fmt::format("{}: cannot create its folder: {}", file.string(), error.message()));
    if (std::filesystem::is_directory(file)) throw std::runtime_error(fmt::format("{}: is a folder", file.string()));
    if (access(folder.c_str(), W_OK) != 0) {
        throw std::runtime_error(fmt::format("{}: its folder is not writable", file.string()));
    }
}

float linearToSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void writeExr(const RgbaImage &film, const std::filesystem::path &file) {
    LayeredImage image;
    image.fullWidth = film.width();
    image.fullHeight = film.height();
    image.dataWindow = {0, 0, film.width(), film.height()};
    image.metadata["Software"] = std::string("veduta");
    const char *names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        std::vector<float> &values = image.addChannel(names[c]);
        for (size_t i = 0; i < values.size(); ++i) values[i] = film.pixels()[i * 4 + size_t(c)];
    }
    writeExr(image, file);
}

std::vector<uint8_t> srgbPixels(const RgbaImage &film) {
    std::vector<uint8_t> pixels(film.pixels().size());
    for (size_t i = 0; i < pixels.size(); ++i) {
        float linear = std::isfinite(film.pixels()[i]) ? film.pixels()[i] : 0.0f;
        float v = (i % 4 == 3) ? std::clamp(linear, 0.0f, 1.0f) : linearToSrgb(linear);
        pixels[i] = uint8_t(std::lround(v * 255.0f));
    }
    return pixels;
}

void writePng(const RgbaImage &film, const std::filesystem::path &file) {
    writeEncodedPng(srgbPixels(film), film.width(), film.height(), 4, file);
}

std::vector<unsigned char> encodePng(const std::vector<uint8_t> &pixels, int width, int height, int channels) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(width);
    image.height = png_uint_32(height);
    image.format = channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, pixels.data(), 0, nullptr))
        throw std::runtime_error(image.message);
    std::vector<unsigned char> bytes(size);
    if (!png_image_write_to_memory(&image, bytes.data(), &size, 0, pixels.data(), 0, nullptr))
        throw std::runtime_error(image.message);
    bytes.resize(size);
    return bytes;
}

void writeEncodedPng(const std::vector<uint8_t> &pixels, int width, int height, int channels,
                     const std::filesystem::path &file) {
    // Encoded in memory so that every write to the disk is checked (libpng's own file writing
    // does not check the close).
    std::vector<unsigned char> bytes;
    try {
        bytes = encodePng(pixels, width, height, channels);
    } catch (const std::runtime_error &e) {
        throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
    }
    writeBytesAtomically(file, bytes.data(), bytes.size());
}

}  // namespace veduta
