#include "film/passes.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/check.h"

namespace veduta {

namespace {

enum class PassId {
    Combined,
    CombinedEven,
    CombinedOdd,
    Depth,
    Normal,
    DiffCol,
    Position,
    IndexOB,
    IndexMA,
    IndexBuilding,
    IndexInstance,
    SampleCount
};

struct Pass {
    PassId id;
    const char *name;
    std::vector<const char *> channels;
    bool data;
};

// Every pass the film develops into, in order.
const Pass kPasses[] = {{PassId::Combined, "Combined", {"R", "G", "B", "A"}, false},
                        {PassId::CombinedEven, "CombinedEven", {"R", "G", "B"}, false},
                        {PassId::CombinedOdd, "CombinedOdd", {"R", "G", "B"}, false},
                        {PassId::Depth, "Depth", {"Z"}, true},
                        {PassId::Normal, "Normal", {"X", "Y", "Z"}, false},
                        {PassId::DiffCol, "DiffCol", {"R", "G", "B"}, false},
                        {PassId::Position, "Position", {"X", "Y", "Z"}, true},
                        {PassId::IndexOB, "IndexOB", {"X"}, true},
                        {PassId::IndexMA, "IndexMA", {"X"}, true},
                        {PassId::IndexBuilding, "IndexBuilding", {"X"}, true},
                        {PassId::IndexInstance, "IndexInstance", {"X"}, true},
                        {PassId::SampleCount, "SampleCount", {"X"}, true}};

const char *const kTopLevelRgba[4] = {"R", "G", "B", "A"};

double inverse(uint32_t count) { return count ? 1.0 / double(count) : 0.0; }

template <typename V>
std::array<float, 4> scaled(const V &v, double scale) {
    return {float(double(v.x) * scale), float(double(v.y) * scale), float(double(v.z) * scale), 0.0f};
}

std::array<float, 4> pixelValues(const Film &film, size_t p, PassId id) {
    uint32_t n = film.sampleCount(p), nEven = film.evenSampleCount(p);
    switch (id) {
    case PassId::Combined: {
        std::array<float, 4> rgba = scaled(film.radianceSum(p), inverse(n));
        // Alpha is 1: the background is part of the image, as in Blender's non-transparent film.
        rgba[3] = 1.0f;
        return rgba;
    }
    case PassId::CombinedEven: return scaled(film.evenRadianceSum(p), inverse(nEven));
    case PassId::CombinedOdd: {
        Vec3d sum = film.radianceSum(p), even = film.evenRadianceSum(p);
        return scaled(Vec3d{sum.x - even.x, sum.y - even.y, sum.z - even.z}, inverse(n - nEven));
    }
    case PassId::Depth: return {film.materialId(p) == 0 ? kBackgroundDepth : film.depth(p)};
    case PassId::Normal: return scaled(film.normalSum(p), inverse(n));
    case PassId::DiffCol: return scaled(film.albedoSum(p), inverse(n));
    case PassId::Position: return scaled(film.position(p), 1.0);
    case PassId::IndexOB: return {float(film.objectId(p))};
    case PassId::IndexMA: return {float(film.materialId(p))};
    case PassId::IndexBuilding: return {float(film.buildingId(p))};
    case PassId::IndexInstance: return {float(film.instanceId(p))};
    case PassId::SampleCount: return {float(n)};
    }
    return {};
}

bool wanted(const DevelopOptions &options, const char *pass) {
    return std::find(options.passes.begin(), options.passes.end(), pass) != options.passes.end();
}

// The ranked ids of every pixel, with the manifest of every name among them.
struct RankedPixels {
    std::vector<std::vector<CryptomatteEntry>> pixels;
    std::map<std::string, std::string> manifest;
};

RankedPixels rankPixels(const Film &film, CryptomatteKind kind, const CryptomatteNaming &naming) {
    RankedPixels ranked;
    std::unordered_map<uint64_t, uint32_t> idOfKey;
    for (size_t p = 0; p < film.pixelCount(); ++p) {
        std::span<const uint64_t> keys = film.cryptomatteKeys(p, kind);
        std::span<const uint32_t> counts = film.cryptomatteCounts(p, kind);
        std::vector<CryptomatteEntry> entries;
        for (size_t slot = 0; slot < keys.size() && counts[slot] > 0; ++slot) {
            auto [it, added] = idOfKey.try_emplace(keys[slot], 0);
            if (added) {
                std::string name = naming(kind, keys[slot]);
                it->second = cryptomatteIdBits(name);
                ranked.manifest[name] = cryptomatteHex(it->second);
            }
            entries.push_back({it->second, double(counts[slot])});
        }
        ranked.pixels.push_back(rankEntries(std::move(entries), film.cryptomatteRanks()));
    }
    return ranked;
}

void developCryptomatte(const Film &film, const DevelopOptions &options, LayeredImage &image) {
    std::vector<std::pair<CryptomatteKind, RankedPixels>> kinds;
    for (CryptomatteKind kind : kCryptomatteKinds) {
        if (!wanted(options, cryptomattePass(kind))) continue;
        VEDUTA_CHECK(film.cryptomatteRanks() > 0 && options.naming,
                     "Cryptomatte needs a film that counts it and names for its ids");
        kinds.emplace_back(kind, rankPixels(film, kind, options.naming));
        addCryptomatteLayers(image, kind, film.cryptomatteRanks(), kinds.back().second.manifest);
    }
    for (const auto &[kind, ranked] : kinds) {
        std::vector<std::vector<float> *> channels = rankChannels(image, kind);
        for (size_t p = 0; p < film.pixelCount(); ++p) {
            storeRanks(channels, p, ranked.pixels[p], double(film.sampleCount(p)));
        }
    }
}

}  // namespace

std::string passChannel(const std::string &pass, const std::string &channel) {
    return fmt::format("{}.{}.{}", kViewLayer, pass, channel);
}

const std::vector<std::string> &allPasses() {
    static const std::vector<std::string> all = [] {
        std::vector<std::string> names;
        for (const Pass &pass : kPasses) names.push_back(pass.name);
        for (CryptomatteKind kind : kCryptomatteKinds) names.push_back(cryptomattePass(kind));
        return names;
    }();
    return all;
}

std::vector<std::string> defaultPasses() {
    std::vector<std::string> names;
    for (const Pass &pass : kPasses) names.push_back(pass.name);
    return names;
}

std::vector<std::string> parsePassList(const std::string &list) {
    if (list == "all") return allPasses();
    std::vector<std::string> passes;
    size_t start = 0;
    for (;;) {
        size_t end = std::min(list.find(',', start), list.size());
        std::string name = list.substr(start, end - start);
        if (std::find(allPasses().begin(), allPasses().end(), name) == allPasses().end()) {
            throw std::invalid_argument(
                fmt::format("unknown pass '{}'; passes: all, {}", name, fmt::join(allPasses(), ", ")));
        }
        if (std::find(passes.begin(), passes.end(), name) == passes.end()) passes.push_back(name);
        if (end == list.size()) return passes;
        start = end + 1;
    }
}

bool isDataChannel(std::string_view channel) {
    if (isCryptomatteChannel(channel)) return true;
    for (const Pass &pass : kPasses) {
        if (channel.starts_with(passChannel(pass.name, ""))) return pass.data;
    }
    return false;
}

LayeredImage developFilm(const Film &film, const DevelopOptions &options) {
    LayeredImage image;
    image.fullWidth = film.fullWidth();
    image.fullHeight = film.fullHeight();
    image.dataWindow = film.window();
    std::vector<const Pass *> passes;
    for (const Pass &pass : kPasses) {
        if (!wanted(options, pass.name)) continue;
        passes.push_back(&pass);
        for (const char *c : pass.channels) image.addChannel(passChannel(pass.name, c));
    }
    if (options.rgba) {
        for (const char *c : kTopLevelRgba) image.addChannel(c);
    }
    // Pointers only once every channel is there: adding one may move the others.
    std::vector<std::vector<std::vector<float> *>> channels;
    for (const Pass *pass : passes) {
        channels.emplace_back();
        for (const char *c : pass->channels) channels.back().push_back(&image.find(passChannel(pass->name, c))->values);
    }
    std::vector<std::vector<float> *> rgba;
    if (options.rgba) {
        for (const char *c : kTopLevelRgba) rgba.push_back(&image.find(c)->values);
    }
    for (size_t p = 0; p < film.pixelCount(); ++p) {
        for (size_t i = 0; i < passes.size(); ++i) {
            std::array<float, 4> values = pixelValues(film, p, passes[i]->id);
            for (size_t c = 0; c < channels[i].size(); ++c) (*channels[i][c])[p] = values[c];
        }
        if (options.rgba) {
            std::array<float, 4> values = pixelValues(film, p, PassId::Combined);
            for (size_t c = 0; c < 4; ++c) (*rgba[c])[p] = values[c];
        }
    }
    developCryptomatte(film, options, image);
    return image;
}

RgbaImage combinedImage(const Film &film) {
    DevelopOptions combined;
    combined.passes = {"Combined"};
    return combinedImage(developFilm(film, combined));
}

RgbaImage combinedImage(const LayeredImage &image) {
    const char *names[4] = {"R", "G", "B", "A"};
    RgbaImage rgba(image.dataWindow.width(), image.dataWindow.height());
    for (int c = 0; c < 4; ++c) {
        const LayeredImage::Channel *channel = image.find(passChannel("Combined", names[c]));
        VEDUTA_CHECK(channel, "the image has no Combined pass");
        for (size_t p = 0; p < channel->values.size(); ++p) rgba.pixels()[p * 4 + size_t(c)] = channel->values[p];
    }
    return rgba;
}

}  // namespace veduta
