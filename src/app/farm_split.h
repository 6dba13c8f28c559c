// How `veduta farm` splits one render into tasks that `veduta merge` puts together again:
// tiles (pixel rectangles) or sample ranges. Pure functions, so that the split is the same
// on every machine that reads the job.
#pragma once

#include <cstdint>
#include <vector>

#include "core/layered_image.h"

namespace veduta {

// `count` rectangles that together cover the width × height image exactly, without overlap,
// each at least one pixel and all of nearly the same area, in rows of nearly square tiles
// (a row may hold one tile more than another, so that any count up to the pixel count
// works, primes included). Rows top to bottom, tiles left to right.
// std::invalid_argument unless 1 ≤ count ≤ width · height.
std::vector<PixelWindow> splitIntoTiles(int width, int height, int count);

struct SampleRange {
    uint32_t offset = 0, samples = 0;  // samples offset … offset + samples − 1
    bool operator==(const SampleRange &) const = default;
};

// `count` ranges that follow each other from 0 to `spp`, their lengths differing by one at
// most. std::invalid_argument unless 1 ≤ count ≤ spp.
std::vector<SampleRange> splitSamples(uint32_t spp, uint32_t count);

}  // namespace veduta
