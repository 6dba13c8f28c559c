// Textures through OpenImageIO's TextureSystem: files converted once into the texture cache
// (src/images/texture_cache.h), looked up with trilinear mip-map filtering. A lookup whose
// footprint spans a whole period of the texture or more gives its mean (the coarsest mip
// level, each of its texels the box-filtered mean of the level above), kept at `add`, without
// a call into OpenImageIO: far surfaces and bounced rays ask for that most of the time. A
// texture of up to kResidentTexels texels is held whole in memory (resident_texture.h) and
// filtered there; larger ones (orthophotos) stream through OpenImageIO's tile cache. An image
// made in memory is held whole, whatever its size, while the resident textures stay within
// kResidentBytes, and otherwise written to the cache as a texture of its own (named by its content)
// and streamed. A procedural texture answers its lookups itself.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <OpenImageIO/texture.h>

#include "images/color_config.h"
#include "images/resident_texture.h"
#include "scene/textures.h"

namespace veduta {

class OiioTextures final : public Textures {
  public:
    static constexpr int64_t kResidentTexels = 1 << 20;  // 1024 × 1024: 21 MB with its mip levels in RGBA
    static constexpr int64_t kResidentBytes = int64_t(512) << 20;

    // `residentBytes` bounds the memory of the textures held whole (kResidentBytes but in tests).
    OiioTextures(std::filesystem::path cacheDirectory, std::shared_ptr<const ColorConfig> config,
                 int64_t residentBytes = kResidentBytes);
    ~OiioTextures() override;
    OiioTextures(const OiioTextures &) = delete;
    OiioTextures &operator=(const OiioTextures &) = delete;

    // Not to be called while lookups run: lookups read the entries without a lock.
    TextureId add(const std::filesystem::path &file, const std::string &colorSpace) override;
    // Equal images share an id.
    TextureId add(Image image) override;
    TextureId add(std::shared_ptr<const ProceduralTexture> texture) override;
    int channels(TextureId id) const override { return entries_.at(id).channels; }
    // The cached texture's name, which is a hash of the file's path, size, time and colour space.
    std::string fingerprint(TextureId id) const override { return entries_.at(id).texture; }
    void lookup(TextureId id, Vec2f uv, float footprint, float *out, int count) const override;

  private:
    struct Entry {
        OIIO::TextureSystem::TextureHandle *handle = nullptr;
        int channels = 0;
        std::string texture;
        std::array<float, 4> mean{};  // the first four channels' means
        std::optional<ResidentTexture> resident;
        std::shared_ptr<const ProceduralTexture> procedural;
    };

    Entry open(const std::filesystem::path &texture, const std::filesystem::path &file);
    TextureId append(Entry entry);
    void filtered(const Entry &entry, Vec2f uv, float footprint, float *out, int count) const;

    std::filesystem::path cacheDirectory_;
    std::shared_ptr<const ColorConfig> config_;
    OIIO::TextureSystem *system_;  // our own, not OpenImageIO's shared one
    std::mutex addMutex_;
    std::map<std::pair<std::string, std::string>, TextureId> ids_;  // (absolute path, colour space)
    std::map<std::string, TextureId> imageIds_;                     // by imageFingerprint
    std::vector<Entry> entries_;
    int64_t residentLimit_;
    int64_t residentBytes_ = 0;
};

}  // namespace veduta
