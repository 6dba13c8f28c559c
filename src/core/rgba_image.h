// A plain picture in memory: linear RGBA float pixels, top row first. What the preview draws
// and what a render develops its combined pass into for PNG and display images.
#pragma once

#include <cstddef>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

class RgbaImage {
  public:
    RgbaImage(int width, int height) :
        width_(width), height_(height), pixels_(size_t(width) * size_t(height) * 4, 0.0f) {}

    int width() const { return width_; }
    int height() const { return height_; }
    // Alpha is 1: the background is part of the image, as in Blender's non-transparent film.
    void set(int x, int y, const Vec3f &rgb) {
        float *p = &pixels_[(size_t(y) * size_t(width_) + size_t(x)) * 4];
        p[0] = rgb.x;
        p[1] = rgb.y;
        p[2] = rgb.z;
        p[3] = 1.0f;
    }
    const float *rgba() const { return pixels_.data(); }
    const std::vector<float> &pixels() const { return pixels_; }
    std::vector<float> &pixels() { return pixels_; }

  private:
    int width_, height_;
    std::vector<float> pixels_;
};

}  // namespace veduta
