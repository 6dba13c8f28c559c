#include "core/murmur_hash.h"

#include <bit>
#include <cstring>

namespace veduta {

namespace {

constexpr uint32_t kC1 = 0xcc9e2d51u, kC2 = 0x1b873593u;

uint32_t scramble(uint32_t k) {
    k *= kC1;
    k = std::rotl(k, 15);
    return k * kC2;
}

uint32_t finalMix(uint32_t h) {
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    return h ^ (h >> 16);
}

}  // namespace

uint32_t murmurHash3(std::string_view bytes, uint32_t seed) {
    static_assert(std::endian::native == std::endian::little, "the blocks are read as little-endian words");
    uint32_t h = seed;
    const size_t blocks = bytes.size() / 4;
    for (size_t i = 0; i < blocks; ++i) {
        uint32_t k;
        std::memcpy(&k, bytes.data() + 4 * i, 4);
        h ^= scramble(k);
        h = std::rotl(h, 13);
        h = h * 5 + 0xe6546b64u;
    }
    uint32_t tail = 0;
    for (size_t i = bytes.size() & ~size_t(3), shift = 0; i < bytes.size(); ++i, shift += 8) {
        tail |= uint32_t(uint8_t(bytes[i])) << shift;
    }
    if (bytes.size() & 3) h ^= scramble(tail);
    return finalMix(h ^ uint32_t(bytes.size()));
}

}  // namespace veduta
