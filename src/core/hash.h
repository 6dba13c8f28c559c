// Integer hashing: the root of every random choice. A choice is a pure function of the scene
// seed and the stable identity of the thing it is made for, never of global state.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace veduta {

// Chris Wellons' "lowbias32" integer finaliser: full avalanche, cheap.
inline uint32_t mix32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// MurmurHash3's 64-bit finaliser.
inline uint64_t mix64(uint64_t k) {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdull;
    k ^= k >> 33;
    k *= 0xc4ceb9fe1a85ec53ull;
    k ^= k >> 33;
    return k;
}

// Hash of an ordered sequence of integers known only at run time (an outline's point ids).
template <typename Values>
uint32_t hashSequence(const Values &values) {
    uint32_t h = 0x9e3779b9u;
    for (uint32_t v : values) h = mix32(h ^ mix32(v + 0x632be5abu));
    return h;
}

// Hash of an ordered list of integers: hashValues({seed, x, y}) != hashValues({seed, y, x}).
inline uint32_t hashValues(std::initializer_list<uint32_t> values) { return hashSequence(values); }

// FNV-1a of a string: a stable key for things known by name (rules), the same on every run.
inline uint32_t hashString(std::string_view text) {
    uint32_t h = 0x811c9dc5u;
    for (unsigned char c : text) h = (h ^ c) * 0x01000193u;
    return mix32(h);
}

// Maps 32 random bits to a float in [0, 1); never returns 1.
inline float bitsToUnitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

}  // namespace veduta
