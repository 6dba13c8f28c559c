#include "render/sampler.h"

#include <array>

namespace veduta {

namespace {

// Dimension 1's generator matrix (dimension 0 is the identity, see sobolSample) as XOR tables
// for each byte of the index: four lookups instead of a loop over 32 bits.
using ByteTables = std::array<std::array<uint32_t, 256>, 4>;

constexpr ByteTables makeDimensionOneTables() {
    // Columns of the Pascal matrix mod 2, for the primitive polynomial x + 1.
    std::array<uint32_t, 32> directions{};
    uint32_t v = 1u << 31;
    for (int bit = 0; bit < 32; ++bit) {
        directions[size_t(bit)] = v;
        v ^= v >> 1;
    }
    ByteTables tables{};
    for (size_t byte = 0; byte < 4; ++byte) {
        for (uint32_t value = 0; value < 256; ++value) {
            uint32_t x = 0;
            for (uint32_t bit = 0; bit < 8; ++bit) {
                if (value & (1u << bit)) x ^= directions[byte * 8 + bit];
            }
            tables[byte][value] = x;
        }
    }
    return tables;
}

constexpr ByteTables kDimensionOne = makeDimensionOneTables();

constexpr uint32_t reversedConstexpr(uint32_t x) {
    uint32_t r = 0;
    for (int bit = 0; bit < 32; ++bit) r |= ((x >> bit) & 1u) << (31 - bit);
    return r;
}

// The same tables with each entry's bits reversed: reversal commutes with XOR, so they give
// the reversed point directly, which is what a scramble starts from.
constexpr ByteTables makeReversed(const ByteTables &tables) {
    ByteTables reversed{};
    for (size_t byte = 0; byte < 4; ++byte)
        for (size_t value = 0; value < 256; ++value) reversed[byte][value] = reversedConstexpr(tables[byte][value]);
    return reversed;
}

constexpr ByteTables kReversedDimensionOne = makeReversed(kDimensionOne);

}  // namespace

uint32_t sobolSample(uint32_t index, int dimension) {
    if (dimension == 0) return reverseBits(index);  // van der Corput
    return kDimensionOne[0][index & 0xffu] ^ kDimensionOne[1][(index >> 8) & 0xffu] ^
        kDimensionOne[2][(index >> 16) & 0xffu] ^ kDimensionOne[3][index >> 24];
}

Vec2f PixelSampler::at(uint32_t pair) const {
    PairSeeds seeds = seeds_ ? seeds_->pair(pair) : pairSeeds(pixelSeed_, pair);
    // owenScramble(sample) is reverseBits of this; Sobol's first dimension is reverseBits of
    // the index, so the index's scramble starts from it as it is.
    uint32_t indexReversed = laineKarras(reversedIndex_, seeds.index);
    uint32_t index = reverseBits(indexReversed);
    uint32_t x = laineKarras(index, seeds.x);
    uint32_t yReversed = kReversedDimensionOne[0][index & 0xffu] ^ kReversedDimensionOne[1][(index >> 8) & 0xffu] ^
        kReversedDimensionOne[2][(index >> 16) & 0xffu] ^ kReversedDimensionOne[3][index >> 24];
    uint32_t y = laineKarras(yReversed, seeds.y);
    return {bitsToUnitFloat(reverseBits(x)), bitsToUnitFloat(reverseBits(y))};
}

}  // namespace veduta
