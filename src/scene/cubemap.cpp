// Stand-in for the cubemap engineer's implementation, only what the sky baker and its tests
// use: construction, texel directions and texel solid angles. Replaced at merge.
#include "scene/cubemap.h"

#include <cmath>

namespace veduta {

const CubeFaceFrame &cubeFaceFrame(int face) {
    // right = forward × up for every face, so each face is seen unmirrored from the centre.
    static const CubeFaceFrame frames[kCubeFaceCount] = {
        {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},   // east
        {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // west
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    // north
        {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}},  // south
        {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   // up: south at the top, east on the right
        {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},   // down: north at the top, east on the right
    };
    return frames[face];
}

Cubemap::Cubemap(int size) : size_(size) {
    for (auto &f : faces_) f.assign(size_t(size) * size_t(size), Vec3f(0.0f));
}

Vec3f Cubemap::direction(int face, float x, float y) const {
    const CubeFaceFrame &f = cubeFaceFrame(face);
    float a = 2 * x / float(size_) - 1, b = 1 - 2 * y / float(size_);
    return normalize(f.forward + f.right * a + f.up * b);
}

float Cubemap::texelSolidAngle(int x, int y) const {
    // The solid angle of the face region [0, a] × [0, b] is atan(a·b / √(a² + b² + 1)).
    auto corner = [](double a, double b) { return std::atan2(a * b, std::sqrt(a * a + b * b + 1)); };
    double a0 = 2.0 * x / size_ - 1, a1 = 2.0 * (x + 1) / size_ - 1;
    double b0 = 1 - 2.0 * (y + 1) / size_, b1 = 1 - 2.0 * y / size_;
    return float(corner(a1, b1) - corner(a0, b1) - corner(a1, b0) + corner(a0, b0));
}

}  // namespace veduta
