#include "scene/shading_normal.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace veduta {

namespace {

// A unit vector, or `fallback` when v is too short to have a direction.
Vec3f normalizeOr(const Vec3f &v, const Vec3f &fallback) {
    float len = length(v);
    return len > 1e-12f ? v / len : fallback;
}

}  // namespace

Vec3f normalFromMap(Vec3f texel, const Vec3f &n, const Vec3f &tangent, float bitangentSign, float strength) {
    Vec3f m = texel * 2.0f - Vec3f(1.0f);
    Vec3f t = normalizeOr(tangent - n * dot(n, tangent), Frame::fromNormal(n).s);
    Vec3f b = cross(n, t) * (bitangentSign < 0 ? -1.0f : 1.0f);
    // A texel of (0.5, 0.5, 0.5) encodes no direction: keep the interpolated normal.
    Vec3f mapped = normalizeOr(t * m.x + b * m.y + n * m.z, n);
    return normalizeOr(n + (mapped - n) * std::max(strength, 0.0f), n);
}

Vec3f ensureValidReflection(const Vec3f &ng, const Vec3f &wo, const Vec3f &n) {
    float threshold = std::min(0.9f * dot(ng, wo), 0.01f);
    Vec3f reflected = n * (2 * dot(n, wo)) - wo;
    if (dot(ng, reflected) >= threshold) return n;

    // Work in the plane of ng (z) and n (x); the corrected normal stays in it, at
    // (√(1 − z²), z). Its mirror image of wo has height 2 (x·Ix + z·Iz) z − Iz, and asking
    // for height t and squaring gives a quadratic in w = z²:
    //   4a w² − 4c w + (t + Iz)² = 0,  a = Ix² + Iz², c = a + t·Iz,
    //   w = (c ± b) / 2a,              b = √(Ix² (a − t²)).
    // Squaring admits a spurious root, the solution for the normal mirrored to (−x, z); the
    // two are told apart by evaluating the height.
    Vec3f x = n - ng * dot(n, ng);
    if (length(x) < 1e-7f) return ng;
    x = normalize(x);
    float ix = dot(wo, x), iz = dot(wo, ng);
    float a = ix * ix + iz * iz;
    float b = std::sqrt(std::max(0.0f, ix * ix * (a - threshold * threshold)));
    float c = a + threshold * iz;

    // Of the candidates with a real z in (0, 1], the true root: the one whose mirror image
    // lies at t. (Cycles 3.4 takes the shallower of two candidates whose mirror images are
    // above the surface, which can be the spurious root, leaving the mirror image between 0
    // and t.)
    bool found = false;
    float bestX = 0, bestZ = 1, bestError = 0;
    for (float w : std::array<float, 2>{(c + b) / (2 * a), (c - b) / (2 * a)}) {
        if (!(w > 1e-5f && w <= 1 + 1e-5f)) continue;
        float nz = std::sqrt(std::min(w, 1.0f)), nx = std::sqrt(std::max(0.0f, 1 - w));
        float error = std::abs(2 * (nx * ix + nz * iz) * nz - iz - threshold);
        if (!found || error < bestError) {
            found = true;
            bestX = nx;
            bestZ = nz;
            bestError = error;
        }
    }
    if (!found) return ng;
    return normalize(x * bestX + ng * bestZ);
}

}  // namespace veduta
