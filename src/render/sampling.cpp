#include "render/sampling.h"

#include <algorithm>

namespace veduta {

Vec2f sampleConcentricDisk(Vec2f u) {
    float a = 2 * u.x - 1, b = 2 * u.y - 1;
    if (a == 0 && b == 0) return {0, 0};
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4) * (b / a);
    } else {
        r = b;
        phi = kPi / 2 - (kPi / 4) * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

Vec3f sampleCosineHemisphere(Vec2f u) {
    Vec2f d = sampleConcentricDisk(u);
    float z = std::sqrt(std::max(0.0f, 1 - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

Vec3f sampleUniformCone(Vec2f u, float oneMinusCosMax) {
    float oneMinusCos = u.x * oneMinusCosMax;
    float cosTheta = 1 - oneMinusCos;
    // sin² = 1 − cos² = (1 − cos)(1 + cos), without the cancellation near cos = 1.
    float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (2 - oneMinusCos)));
    float phi = 2 * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

}  // namespace veduta
