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

// Writes `image` (linear) as a tiled, mip-mapped texture; `source` names it in errors.
void writeTexture(const Image &image, const std::string &source, const std::filesystem::path &texture) {
    OIIO::ImageBuf input(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeFloat),
                         const_cast<float *>(image.pixels.data()));  // only read
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
                fmt::format("{}: cannot make the texture {}: {}", source, texture.string(), OIIO::geterror()));
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
    // Linearised before mip-mapping, so that the mip levels average light, not encoded values.
    if (!std::filesystem::exists(texture))
        writeTexture(readImageFile(file, colorSpace, config), file.string(), texture);
    return texture;
}

std::string imageFingerprint(const Image &image) {
    std::string size =
        fmt::format("{}\n{}\n{}\n{}\n", kTextureFormatVersion, image.width, image.height, image.channels);
    uint64_t pixels = OIIO::farmhash::Fingerprint64(reinterpret_cast<const char *>(image.pixels.data()),
                                                    image.pixels.size() * sizeof(float));
    return fmt::format("{:016x}-{:016x}", OIIO::farmhash::Fingerprint64(size), pixels);
}

std::filesystem::path cachedImageTexturePath(const std::filesystem::path &cacheDirectory,
                                             const std::string &fingerprint) {
    return cacheDirectory / fmt::format("image-{}.tx", fingerprint);
}

std::filesystem::path cachedImageTexture(const std::filesystem::path &cacheDirectory, const Image &image,
                                         const std::string &fingerprint) {
    std::filesystem::path texture = cachedImageTexturePath(cacheDirectory, fingerprint);
    if (!std::filesystem::exists(texture)) writeTexture(image, "an image made in memory", texture);
    return texture;
}

}  // namespace veduta
