#include "scene/lobe_weights.h"

#include <algorithm>

namespace veduta {

namespace {

Vec3f clamp01(const Vec3f &c) {
    return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

Vec3f nonNegative(const Vec3f &c) { return {std::max(c.x, 0.0f), std::max(c.y, 0.0f), std::max(c.z, 0.0f)}; }

}  // namespace

LobeWeights lobeWeights(const Vec3f &diffuse, const Vec3f &specular, const Vec3f &mirror) {
    LobeWeights w;
    w.mirror = clamp01(mirror);
    Vec3f kd = nonNegative(diffuse), ks = nonNegative(specular);
    float sum = maxComponent(kd + ks);
    if (sum > 1) {
        kd = kd / sum;
        ks = ks / sum;
    }
    Vec3f rest = Vec3f(1.0f) - w.mirror;
    w.diffuse = kd * rest;
    w.specular = ks * rest;
    return w;
}

}  // namespace veduta
