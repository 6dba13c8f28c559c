#include "images/texture_cache.h"

#include <stdexcept>

#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "images/image_files.h"

namespace veduta {

namespace {

// Raise when the conversion changes, so that textures made by older builds are not reused.
constexpr int kTextureFormatVersion = 1;
constexpr int kTileSize = 64;

void convertToTexture(const std::filesystem::path &file, const std::string &colorSpace, const ColorConfig &config,
                      const std::filesystem::path &texture) {
    // Linearised before mip-mapping, so that the mip levels average light, not encoded values.
    Image image = readImageFile(file, colorSpace, config);
    OIIO::ImageBuf input(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeFloat),
                         image.pixels.data());
    // Float: OpenImageIO's TIFF writer, which .tx files go through, has no half.
    OIIO::ImageSpec settings(0, 0, 0, OIIO::TypeFloat);
    settings.tile_width = settings.tile_height = kTileSize;
    settings.tile_depth = 1;
    settings.attribute("compression", "zip");
    settings.attribute("wrapmodes", "periodic,periodic");
    settings.attribute("maketx:filtername", "box");  // each mip texel the mean of the texels it covers
    writeFileAtomically(texture, [&](const std::filesystem::path &temporary) {
        if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, input, temporary.string(), settings)) {
            throw std::runtime_error(
                fmt::format("{}: cannot make the texture {}: {}", file.string(), texture.string(), OIIO::geterror()));
        }
    });
}

}  // namespace

std::filesystem::path cachedTexturePath(const std::filesystem::path &cacheDirectory, const std::filesystem::path &file,
                                        const std::string &colorSpace) {
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::absolute(file, error);
    uintmax_t size = error ? 0 : std::filesystem::file_size(absolute, error);
    std::filesystem::file_time_type modified =
        error ? std::filesystem::file_time_type{} : std::filesystem::last_write_time(absolute, error);
    if (error) throw InputError(FileLoc{file.string()}, error.message());
    std::string key = fmt::format("{}\n{}\n{}\n{}\n{}", kTextureFormatVersion, absolute.string(), size,
                                  modified.time_since_epoch().count(), colorSpace);
    return cacheDirectory / fmt::format("{:016x}.tx", OIIO::farmhash::Fingerprint64(key));
}

std::filesystem::path cachedTexture(const std::filesystem::path &cacheDirectory, const std::filesystem::path &file,
                                    const std::string &colorSpace, const ColorConfig &config) {
    std::filesystem::path texture = cachedTexturePath(cacheDirectory, file, colorSpace);
    if (!std::filesystem::exists(texture)) convertToTexture(file, colorSpace, config, texture);
    return texture;
}

}  // namespace veduta
