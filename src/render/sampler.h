// The sample generator: Owen-scrambled Sobol points (Burley 2020, "Practical Hash-based Owen
// Scrambling"), padded in 2D pairs. Every value is a pure function of (seed, pixel, sample
// index, dimension), so an image does not depend on thread count, tile size or region.
#pragma once

#include <cstdint>

#include "core/hash.h"
#include "core/random_streams.h"
#include "core/vecmath.h"

namespace veduta {

uint32_t sobolSample(uint32_t index, int dimension);  // dimension 0 or 1

inline uint32_t reverseBits(uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    return __builtin_bswap32(x);
}

// Laine-Karras style permutation with Vegdahl's constants: a nested uniform (Owen) scramble
// of reversed bits.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) {
    x = reverseBits(x);
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return reverseBits(x);
}

class PixelSampler {
  public:
    PixelSampler(uint32_t seed, uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex) :
        pixelSeed_(hashValues({seed * streamTag(RandomStream::Sampler), pixelX, pixelY})), sampleIndex_(sampleIndex) {}

    // Each call consumes one dimension pair; the pair index is the "dimension" of the contract.
    // The two constants give each coordinate of the pair a scramble of its own.
    Vec2f next2D() {
        uint32_t pairSeed = hashValues({pixelSeed_, pair_++});
        uint32_t index = owenScramble(sampleIndex_, pairSeed);
        return {bitsToUnitFloat(owenScramble(sobolSample(index, 0), mix32(pairSeed ^ 0xa511e9b3u))),
                bitsToUnitFloat(owenScramble(sobolSample(index, 1), mix32(pairSeed ^ 0x63d83595u)))};
    }
    float next1D() { return next2D().x; }

  private:
    uint32_t pixelSeed_;
    uint32_t sampleIndex_;
    uint32_t pair_ = 0;
};

}  // namespace veduta
