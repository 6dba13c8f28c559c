#include "images/oiio_textures.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.h"
#include "images/image_files.h"
#include "images/texture_cache.h"

namespace veduta {

OiioTextures::OiioTextures(std::filesystem::path cacheDirectory, std::shared_ptr<const ColorConfig> config,
                           int64_t residentBytes) :
    cacheDirectory_(std::move(cacheDirectory)),
    config_(std::move(config)),
    system_(OIIO::TextureSystem::create(/*shared=*/false)),
    residentLimit_(residentBytes) {}

OiioTextures::~OiioTextures() { OIIO::TextureSystem::destroy(system_, /*teardown_imagecache=*/true); }

TextureId OiioTextures::add(const std::filesystem::path &file, const std::string &colorSpace) {
    // The resolved name, so that "" and the file's own space, or an alias and its name, share an id.
    std::string space = fileColorSpace(file, readImageSpec(file), colorSpace, *config_);
    std::lock_guard lock(addMutex_);
    auto key = std::make_pair(std::filesystem::absolute(file).lexically_normal().string(), space);
    if (auto found = ids_.find(key); found != ids_.end()) return found->second;
    TextureId id = append(open(cachedTexture(cacheDirectory_, file, space, *config_), file));
    ids_.emplace(key, id);
    return id;
}

TextureId OiioTextures::add(Image image) {
    if (image.empty() || image.channels < 1 || image.channels > 4)
        throw std::invalid_argument(
            fmt::format("a texture of {} × {} texels in {} channels", image.width, image.height, image.channels));
    std::string fingerprint = imageFingerprint(image);
    std::lock_guard lock(addMutex_);
    if (auto found = imageIds_.find(fingerprint); found != imageIds_.end()) return found->second;
    int64_t bytes = ResidentTexture::bytesFor(image.width, image.height, image.channels);
    Entry entry;
    if (residentBytes_ + bytes <= residentLimit_) {
        entry.texture = cachedImageTexturePath(cacheDirectory_, fingerprint).filename().string();  // as if streamed
        entry.channels = image.channels;
        entry.resident = ResidentTexture::fromImage(std::move(image));
        residentBytes_ += bytes;
    } else {
        std::filesystem::path texture = cachedImageTexture(cacheDirectory_, image, fingerprint);
        entry = open(texture, texture);
    }
    TextureId id = append(std::move(entry));
    imageIds_.emplace(fingerprint, id);
    return id;
}

TextureId OiioTextures::add(std::shared_ptr<const ProceduralTexture> texture) {
    Entry entry;
    entry.channels = texture->channels();
    entry.texture = "procedural:" + texture->fingerprint();
    entry.procedural = std::move(texture);
    std::lock_guard lock(addMutex_);
    return append(std::move(entry));
}

// Adds the entry with its mean: a footprint far wider than the texture reads the coarsest level.
// A procedural texture filters for itself (lookup) and is not asked now: it may compute its values
// only when they are first looked up.
TextureId OiioTextures::append(Entry entry) {
    constexpr float kWholeTexture = 1e6f;
    if (!entry.procedural)
        filtered(entry, {0.5f, 0.5f}, kWholeTexture, entry.mean.data(),
                 std::min(entry.channels, int(entry.mean.size())));
    entries_.push_back(std::move(entry));
    return TextureId(entries_.size() - 1);
}

OiioTextures::Entry OiioTextures::open(const std::filesystem::path &texture, const std::filesystem::path &file) {
    Entry entry;
    entry.texture = texture.filename().string();
    entry.handle = system_->get_texture_handle(OIIO::ustring(texture.string()));
    if (!entry.handle ||
        !system_->get_texture_info(entry.handle, nullptr, 0, OIIO::ustring("channels"), OIIO::TypeInt,
                                   &entry.channels)) {
        throw InputError(FileLoc{file.string()},
                         fmt::format("cannot open its texture {}: {}", texture.string(), system_->geterror()));
    }
    try {
        entry.resident = ResidentTexture::read(texture, kResidentTexels);
        if (entry.resident && residentBytes_ + entry.resident->bytes() > residentLimit_) entry.resident.reset();
        if (entry.resident) residentBytes_ += entry.resident->bytes();
    } catch (const std::runtime_error &e) {
        throw InputError(FileLoc{file.string()}, fmt::format("cannot read its texture: {}", e.what()));
    }
    return entry;
}

void OiioTextures::lookup(TextureId id, Vec2f uv, float footprint, float *out, int count) const {
    const Entry &entry = entries_[id];
    // A procedural texture's (u, v) and footprint are its own: it filters for itself.
    if (footprint >= 1 && count <= int(entry.mean.size()) && !entry.procedural) {
        std::copy_n(entry.mean.begin(), std::min(count, entry.channels), out);
        return;
    }
    filtered(entry, uv, footprint, out, count);
}

void OiioTextures::filtered(const Entry &entry, Vec2f uv, float footprint, float *out, int count) const {
    if (entry.procedural) {
        entry.procedural->lookup(uv, footprint, out, count);
        return;
    }
    if (entry.resident) {
        entry.resident->lookup(uv, footprint, out, count);
        return;
    }
    OIIO::TextureOpt options;
    options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
    options.mipmode = OIIO::TextureOpt::MipModeTrilinear;  // deterministic, unlike the stochastic modes
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    // OpenImageIO's t runs down from the top row; our v runs up.
    float s = uv.x, t = 1.0f - uv.y;
    if (!system_->texture(entry.handle, system_->get_perthread_info(), options, s, t, footprint, 0.0f, 0.0f, footprint,
                          std::min(count, entry.channels), out)) {
        throw std::runtime_error(fmt::format("texture lookup failed: {}", system_->geterror()));
    }
}

}  // namespace veduta
