// An image in memory: float samples, interleaved channels, the top row first. What image
// files become when read (src/images/) and what cubemap conversions work on.
#pragma once

#include <cstddef>
#include <vector>

namespace veduta {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // width · height · channels samples

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c), pixels(size_t(w) * size_t(h) * size_t(c), 0.0f) {}

    float *at(int x, int y) { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels)]; }
    const float *at(int x, int y) const { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels)]; }
    bool empty() const { return pixels.empty(); }
};

}  // namespace veduta
