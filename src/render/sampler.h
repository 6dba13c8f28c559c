// The sample generator: Owen-scrambled Sobol points (Burley 2020, "Practical Hash-based Owen
// Scrambling"), padded in 2D pairs. Every value is a pure function of (seed, pixel, sample
// index, dimension), so an image does not depend on thread count, tile size or region.
#pragma once

#include <array>
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

// The hash of owenScramble, on bits already reversed: Laine-Karras style, with Vegdahl's
// constants.
inline uint32_t laineKarras(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// A nested uniform (Owen) scramble of x's bits, most significant first.
inline uint32_t owenScramble(uint32_t x, uint32_t seed) { return reverseBits(laineKarras(reverseBits(x), seed)); }

// The scrambles of one dimension pair: of the sample index, and of each coordinate.
struct PairSeeds {
    uint32_t index, x, y;
};

inline PairSeeds pairSeeds(uint32_t pixelSeed, uint32_t pair) {
    uint32_t seed = hashValues({pixelSeed, pair});
    return {seed, mix32(seed ^ 0xa511e9b3u), mix32(seed ^ 0x63d83595u)};
}

inline uint32_t pixelSeed(uint32_t seed, uint32_t pixelX, uint32_t pixelY) {
    return hashValues({seed * streamTag(RandomStream::Sampler), pixelX, pixelY});
}

// The pair seeds of one pixel, which all its samples share: worked out once per pixel and
// pair, as its samples first ask for them, rather than once per sample. Not thread-safe: one
// per pixel being sampled.
class PixelSeeds {
  public:
    static constexpr uint32_t kPairs = 32;  // those kept; later pairs are worked out each time

    PixelSeeds(uint32_t seed, uint32_t pixelX, uint32_t pixelY) : pixelSeed_(pixelSeed(seed, pixelX, pixelY)) {}

    uint32_t pixel() const { return pixelSeed_; }
    PairSeeds pair(uint32_t index) {
        if (index >= kPairs) return pairSeeds(pixelSeed_, index);
        while (filled_ <= index) {
            pairs_[filled_] = pairSeeds(pixelSeed_, filled_);
            ++filled_;
        }
        return pairs_[index];
    }

  private:
    uint32_t pixelSeed_;
    uint32_t filled_ = 0;
    std::array<PairSeeds, kPairs> pairs_;
};

class PixelSampler {
  public:
    PixelSampler(uint32_t seed, uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex) :
        pixelSeed_(pixelSeed(seed, pixelX, pixelY)), reversedIndex_(reverseBits(sampleIndex)) {}
    // The same points, with the pixel's pair seeds kept in `seeds` (which must outlive it).
    PixelSampler(PixelSeeds &seeds, uint32_t sampleIndex) :
        pixelSeed_(seeds.pixel()), reversedIndex_(reverseBits(sampleIndex)), seeds_(&seeds) {}

    // Each call consumes one dimension pair; the pair index is the "dimension" of the contract.
    // The pair's point is that of the scrambled sample index in the first two Sobol
    // dimensions, each coordinate scrambled on its own (s = pairSeeds(pixel, pair)):
    //   index = owenScramble(sample, s.index)
    //   point = (owenScramble(sobolSample(index, 0), s.x), owenScramble(sobolSample(index, 1), s.y))
    // worked out with three bit reversals instead of seven (sampler.cpp).
    Vec2f next2D() { return at(pair_++); }
    float next1D() { return next2D().x; }
    // Takes `count` pairs at once for a consumer that may use only some of them (a path vertex
    // whose ray escapes needs none of its light and bounce pairs): it works out those it uses
    // with at(first + k), and the pairs after them keep their meaning either way.
    uint32_t take(uint32_t count) {
        uint32_t first = pair_;
        pair_ += count;
        return first;
    }
    Vec2f at(uint32_t pair) const;

  private:
    uint32_t pixelSeed_;
    uint32_t reversedIndex_;  // the sample index, bits reversed
    PixelSeeds *seeds_ = nullptr;
    uint32_t pair_ = 0;
};

}  // namespace veduta
