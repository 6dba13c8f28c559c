#include "film/cryptomatte.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/json_text.h"
#include "core/murmur_hash.h"
#include "film/passes.h"
#include "scene/object_names.h"

namespace veduta {

namespace {

const char *const kRankChannels[2][2] = {{"R", "G"}, {"B", "A"}};  // [rank % 2][coverage]

std::string layerName(CryptomatteKind kind, int layer) { return fmt::format("{}{:02d}", cryptomattePass(kind), layer); }

// A reader of the JSON manifestJson writes: one object of string members.
class ManifestReader {
  public:
    explicit ManifestReader(const std::string &json) : json_(json) {}

    std::map<std::string, std::string> read() {
        std::map<std::string, std::string> manifest;
        expect('{');
        if (peek() == '}') return ++at_, manifest;
        for (;;) {
            std::string name = string();
            expect(':');
            manifest[name] = string();
            if (peek() == '}') return ++at_, manifest;
            expect(',');
        }
    }

  private:
    char peek() {
        while (at_ < json_.size() && json_[at_] == ' ') ++at_;
        if (at_ >= json_.size()) throw std::runtime_error("the Cryptomatte manifest ends early");
        return json_[at_];
    }
    void expect(char c) {
        if (peek() != c) throw std::runtime_error(fmt::format("the Cryptomatte manifest lacks a '{}'", c));
        ++at_;
    }
    // The character JSON's one-letter escape `\c` stands for (`\"`, `\\` and `\/` for themselves).
    static char escaped(char c) {
        switch (c) {
        case 'b': return '\b';
        case 'f': return '\f';
        case 'n': return '\n';
        case 'r': return '\r';
        case 't': return '\t';
        default: return c;
        }
    }
    // The four hex digits after `\u`.
    uint32_t codePoint() {
        if (at_ + 4 > json_.size()) throw std::runtime_error("the Cryptomatte manifest ends inside a \\u escape");
        uint32_t value = 0;
        for (size_t end = at_ + 4; at_ < end; ++at_) {
            char c = json_[at_];
            int digit = std::isdigit(uint8_t(c)) ? c - '0'
                : std::isxdigit(uint8_t(c))      ? std::tolower(c) - 'a' + 10
                                                 : -1;
            if (digit < 0)
                throw std::runtime_error("the Cryptomatte manifest has a \\u escape that is not four hex digits");
            value = value * 16 + uint32_t(digit);
        }
        return value;
    }
    // A code point of the Basic Multilingual Plane as UTF-8 (names are UTF-8 in the header).
    static void appendUtf8(std::string &text, uint32_t code) {
        if (code < 0x80) {
            text += char(code);
        } else if (code < 0x800) {
            text += char(0xC0 | (code >> 6));
            text += char(0x80 | (code & 0x3F));
        } else {
            text += char(0xE0 | (code >> 12));
            text += char(0x80 | ((code >> 6) & 0x3F));
            text += char(0x80 | (code & 0x3F));
        }
    }
    std::string string() {
        expect('"');
        std::string text;
        while (at_ < json_.size() && json_[at_] != '"') {
            char c = json_[at_++];
            if (c == '\\' && at_ < json_.size()) {
                c = json_[at_++];
                if (c == 'u') {
                    appendUtf8(text, codePoint());
                    continue;
                }
                c = escaped(c);
            }
            text += c;
        }
        expect('"');
        return text;
    }

    const std::string &json_;
    size_t at_ = 0;
};

}  // namespace

const char *cryptomattePass(CryptomatteKind kind) {
    switch (kind) {
    case CryptomatteKind::Object: return "CryptoObject";
    case CryptomatteKind::Material: return "CryptoMaterial";
    }
    return "";
}

std::string cryptomatteTypeName(CryptomatteKind kind) {
    return fmt::format("{}.{}", kViewLayer, cryptomattePass(kind));
}

std::string cryptomatteMetadataPrefix(const std::string &typeName) {
    return fmt::format("cryptomatte/{}/", cryptomatteHex(murmurHash3(typeName)).substr(0, 7));
}

int cryptomatteLayers(int ranks) { return (ranks + 1) / 2; }

std::string cryptomatteChannel(CryptomatteKind kind, int rank, bool coverage) {
    return passChannel(layerName(kind, rank / 2), kRankChannels[rank % 2][coverage]);
}

bool isCryptomatteChannel(std::string_view channel) {
    for (CryptomatteKind kind : kCryptomatteKinds) {
        if (channel.starts_with(cryptomatteTypeName(kind))) return true;
    }
    return false;
}

uint32_t cryptomatteIdBits(std::string_view name) {
    uint32_t hash = murmurHash3(name);
    uint32_t exponent = (hash >> 23) & 0xffu;
    // Exponent 0 (zero, denormals) becomes 1 and 255 (infinities, NaNs) becomes 254.
    if (exponent == 0 || exponent == 255) hash ^= 1u << 23;
    return hash;
}

float cryptomatteId(std::string_view name) { return std::bit_cast<float>(cryptomatteIdBits(name)); }

std::string cryptomatteHex(uint32_t idBits) { return fmt::format("{:08x}", idBits); }

uint64_t cryptomatteObjectKey(ObjectId objectId, uint32_t buildingId) {
    return uint64_t(buildingId) << 32 | uint64_t(objectId);
}

CryptomatteNaming cryptomatteNaming(const RenderScene &scene) {
    std::vector<std::string> materials;
    for (const Material &m : scene.materials) materials.push_back(m.name);
    return [materials = std::move(materials)](CryptomatteKind kind, uint64_t key) {
        if (kind == CryptomatteKind::Object) return objectName(ObjectId(key & 0xffffffffu), uint32_t(key >> 32));
        // Material keys are the film's material ids, 1 + the index; a hit always has one.
        return materials.at(key - 1);
    };
}

std::vector<CryptomatteEntry> rankEntries(std::vector<CryptomatteEntry> entries, int ranks) {
    std::sort(entries.begin(), entries.end(), [](const CryptomatteEntry &a, const CryptomatteEntry &b) {
        return a.weight != b.weight ? a.weight > b.weight : a.idBits < b.idBits;
    });
    if (entries.size() > size_t(ranks)) entries.resize(size_t(ranks));
    return entries;
}

void addCryptomatteLayers(LayeredImage &image, CryptomatteKind kind, int ranks,
                          const std::map<std::string, std::string> &manifest) {
    for (int rank = 0; rank < 2 * cryptomatteLayers(ranks); ++rank) {
        image.addChannel(cryptomatteChannel(kind, rank, false));
        image.addChannel(cryptomatteChannel(kind, rank, true));
    }
    std::string type = cryptomatteTypeName(kind), prefix = cryptomatteMetadataPrefix(type);
    image.metadata[prefix + "name"] = type;
    image.metadata[prefix + "hash"] = std::string("MurmurHash3_32");
    image.metadata[prefix + "conversion"] = std::string("uint32_to_float32");
    image.metadata[prefix + "manifest"] = manifestJson(manifest);
}

std::vector<std::vector<float> *> rankChannels(LayeredImage &image, CryptomatteKind kind) {
    std::vector<std::vector<float> *> channels;
    for (int rank = 0, n = storedRanks(image, kind); rank < n; ++rank) {
        for (bool coverage : {false, true})
            channels.push_back(&image.find(cryptomatteChannel(kind, rank, coverage))->values);
    }
    return channels;
}

std::vector<const std::vector<float> *> rankChannels(const LayeredImage &image, CryptomatteKind kind) {
    std::vector<std::vector<float> *> channels = rankChannels(const_cast<LayeredImage &>(image), kind);
    return {channels.begin(), channels.end()};
}

void storeRanks(const std::vector<std::vector<float> *> &channels, size_t pixel,
                const std::vector<CryptomatteEntry> &ranked, double samples) {
    for (size_t rank = 0; rank < ranked.size(); ++rank) {
        (*channels[2 * rank])[pixel] = std::bit_cast<float>(ranked[rank].idBits);
        (*channels[2 * rank + 1])[pixel] = float(ranked[rank].weight / samples);
    }
}

int storedRanks(const LayeredImage &image, CryptomatteKind kind) {
    int ranks = 0;
    while (ranks < kMaxCryptomatteRanks && image.find(cryptomatteChannel(kind, ranks, false))) ++ranks;
    return ranks;
}

std::vector<CryptomatteEntry> readRanks(const std::vector<const std::vector<float> *> &channels, size_t pixel,
                                        double samples) {
    std::vector<CryptomatteEntry> entries;
    for (size_t rank = 0; 2 * rank < channels.size(); ++rank) {
        float coverage = (*channels[2 * rank + 1])[pixel];
        if (coverage > 0) {
            float id = (*channels[2 * rank])[pixel];
            entries.push_back({std::bit_cast<uint32_t>(id), std::round(double(coverage) * samples)});
        }
    }
    return entries;
}

std::string manifestJson(const std::map<std::string, std::string> &manifest) {
    std::string json = "{";
    for (const auto &[name, hex] : manifest) {
        if (json.size() > 1) json += ',';
        json += jsonString(name) + ":" + jsonString(hex);
    }
    return json + "}";
}

std::map<std::string, std::string> parseManifest(const std::string &json) { return ManifestReader(json).read(); }

std::map<std::string, std::string> storedManifest(const LayeredImage &image, CryptomatteKind kind) {
    auto it = image.metadata.find(cryptomatteMetadataPrefix(cryptomatteTypeName(kind)) + "manifest");
    if (it == image.metadata.end()) return {};
    const std::string *json = std::get_if<std::string>(&it->second);
    if (!json) throw std::runtime_error(fmt::format("its {} manifest is not a string", cryptomattePass(kind)));
    return parseManifest(*json);
}

}  // namespace veduta
