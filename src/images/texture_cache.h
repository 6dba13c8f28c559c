// Image files converted to tiled, mip-mapped textures in linear values (OpenImageIO's .tx,
// what maketx makes), kept in a cache folder so that later runs reuse them.
#pragma once

#include <filesystem>
#include <string>

#include "core/image.h"
#include "images/color_config.h"

namespace veduta {

// The cached texture for `file` read in `colorSpace` (a config name): its name is a hash of
// the absolute path, size, modification time, colour space and the conversion's version, so a
// changed file gets a new one. Throws InputError naming the file when it cannot be read.
std::filesystem::path cachedTexturePath(const std::filesystem::path &cacheDirectory, const std::filesystem::path &file,
                                        const std::string &colorSpace);

// Returns the cached texture, converting `file` first if the cache lacks it. The texture is
// written atomically, so runs in parallel never read half a file. Throws InputError naming the
// file when it cannot be read, std::runtime_error when the texture cannot be written.
std::filesystem::path cachedTexture(const std::filesystem::path &cacheDirectory, const std::filesystem::path &file,
                                    const std::string &colorSpace, const ColorConfig &config);

// A name for the values of an image made in memory (its size, channels and pixels' bits).
std::string imageFingerprint(const Image &image);

// Where the cached texture of an image with that fingerprint goes.
std::filesystem::path cachedImageTexturePath(const std::filesystem::path &cacheDirectory,
                                             const std::string &fingerprint);

// The cached texture of an image made in memory (linear), named by its fingerprint, written
// first if the cache lacks it. Throws std::runtime_error when it cannot be written.
std::filesystem::path cachedImageTexture(const std::filesystem::path &cacheDirectory, const Image &image,
                                         const std::string &fingerprint);

}  // namespace veduta
