#include "render/sampler.h"

#include <array>

namespace veduta {

namespace {

// Generator matrices of the first two Sobol dimensions: the identity (van der Corput) and
// the Pascal matrix mod 2 (primitive polynomial x + 1).
constexpr std::array<std::array<uint32_t, 32>, 2> makeSobolDirections() {
    std::array<std::array<uint32_t, 32>, 2> d{};
    uint32_t v = 1u << 31;
    for (int bit = 0; bit < 32; ++bit) {
        d[0][bit] = 1u << (31 - bit);
        d[1][bit] = v;
        v ^= v >> 1;
    }
    return d;
}

constexpr auto kSobolDirections = makeSobolDirections();

}  // namespace

uint32_t sobolSample(uint32_t index, int dimension) {
    uint32_t x = 0;
    for (int bit = 0; index != 0; index >>= 1, ++bit) {
        if (index & 1u) x ^= kSobolDirections[dimension][bit];
    }
    return x;
}

}  // namespace veduta
