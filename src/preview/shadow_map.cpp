#include "preview/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace veduta {

namespace {

constexpr float kNothing = -std::numeric_limits<float>::infinity();

// Placed mesh i of the scene: the baked meshes, then one per instance.
size_t placedCount(const RenderScene &scene) { return scene.meshes.size() + scene.instances.size(); }

const Mesh &placedMesh(const RenderScene &scene, size_t i) {
    return i < scene.meshes.size() ? scene.meshes[i].mesh
                                   : scene.prototypes[scene.instances[i - scene.meshes.size()].prototype];
}

Transform placedTransform(const RenderScene &scene, size_t i) {
    return i < scene.meshes.size() ? Transform{} : scene.instances[i - scene.meshes.size()].objectToWorld;
}

}  // namespace

ShadowMap::ShadowMap(const RenderScene &scene, int size) :
    frame_(Frame::fromNormal(scene.sun.direction)), size_(size), height_(size_t(size) * size_t(size), kNothing) {
    // The map's extent: the corners of every placed mesh's box, in the sun's frame.
    std::vector<std::pair<Vec3f, Vec3f>> prototypeBoxes;
    auto boxOf = [](const Mesh &m) {
        Vec3f lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
        for (const Vec3f &p : m.positions)
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)},
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        return std::make_pair(lo, hi);
    };
    for (const Mesh &p : scene.prototypes) prototypeBoxes.push_back(boxOf(p));
    float uMin = std::numeric_limits<float>::infinity(), vMin = uMin, uMax = -uMin, vMax = -uMin;
    for (size_t i = 0; i < placedCount(scene); ++i) {
        if (placedMesh(scene, i).vertexCount() == 0) continue;
        auto [lo, hi] = i < scene.meshes.size() ? boxOf(scene.meshes[i].mesh)
                                                : prototypeBoxes[scene.instances[i - scene.meshes.size()].prototype];
        Transform toWorld = placedTransform(scene, i);
        for (int c = 0; c < 8; ++c) {
            Vec3f p = toWorld.applyPoint({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
            float u = dot(p, frame_.s), v = dot(p, frame_.t);
            uMin = std::min(uMin, u), uMax = std::max(uMax, u), vMin = std::min(vMin, v), vMax = std::max(vMax, v);
        }
    }
    if (!(uMax >= uMin)) return;  // nothing to cast shadows
    originU_ = uMin;
    originV_ = vMin;
    texelsPerMetre_ = float(size) / std::max({uMax - uMin, vMax - vMin, 1e-3f});

    // Each thread draws its share of the meshes into a map of its own; the maps are merged by
    // taking the highest surface, which does not depend on the order, so neither does the result.
    tbb::enumerable_thread_specific<std::vector<float>> maps(
        [&] { return std::vector<float>(height_.size(), kNothing); });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, placedCount(scene)), [&](const tbb::blocked_range<size_t> &r) {
        std::vector<float> &map = maps.local();
        std::vector<Vec3f> light;
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const Mesh &mesh = placedMesh(scene, i);
            Transform toWorld = placedTransform(scene, i);
            light.resize(mesh.vertexCount());
            for (size_t v = 0; v < light.size(); ++v) light[v] = lightSpace(toWorld.applyPoint(mesh.positions[v]));
            draw(light, mesh, map);
        }
    });
    for (const std::vector<float> &map : maps) {
        for (size_t t = 0; t < height_.size(); ++t) height_[t] = std::max(height_[t], map[t]);
    }
}

void ShadowMap::draw(const std::vector<Vec3f> &v, const Mesh &mesh, std::vector<float> &map) const {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3f &a = v[mesh.indices[3 * t]], &b = v[mesh.indices[3 * t + 1]], &c = v[mesh.indices[3 * t + 2]];
        int x0 = int(std::ceil(std::clamp(std::min({a.x, b.x, c.x}) - 0.5f, 0.0f, float(size_))));
        int x1 = int(std::floor(std::clamp(std::max({a.x, b.x, c.x}) - 0.5f, -1.0f, float(size_ - 1))));
        int y0 = int(std::ceil(std::clamp(std::min({a.y, b.y, c.y}) - 0.5f, 0.0f, float(size_))));
        int y1 = int(std::floor(std::clamp(std::max({a.y, b.y, c.y}) - 0.5f, -1.0f, float(size_ - 1))));
        if (x0 > x1 || y0 > y1) continue;
        float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (area == 0 || !std::isfinite(area)) continue;
        float inv = 1.0f / area;
        for (int y = y0; y <= y1; ++y) {
            float py = float(y) + 0.5f;
            for (int x = x0; x <= x1; ++x) {
                float px = float(x) + 0.5f;
                // Barycentrics; orthographic, so heights interpolate linearly. The small
                // tolerance closes cracks between neighbours: heights take the maximum, so
                // overlap costs nothing.
                float wb = ((px - a.x) * (c.y - a.y) - (c.x - a.x) * (py - a.y)) * inv;
                float wc = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) * inv;
                float wa = 1 - wb - wc;
                if (std::min({wa, wb, wc}) < -1e-4f) continue;
                float &h = map[size_t(y) * size_t(size_) + size_t(x)];
                h = std::max(h, wa * a.z + wb * b.z + wc * c.z);
            }
        }
    }
}

Vec3f ShadowMap::lightSpace(const Vec3f &p) const {
    return {(dot(p, frame_.s) - originU_) * texelsPerMetre_, (dot(p, frame_.t) - originV_) * texelsPerMetre_,
            dot(p, frame_.n)};
}

bool ShadowMap::shadowed(const Vec3f &p, const Vec3f &n) const {
    Vec3f l = lightSpace(p);
    int x = int(std::floor(l.x)), y = int(std::floor(l.y));
    if (!(l.x >= 0 && l.y >= 0) || x >= size_ || y >= size_) return false;
    // A surface tilted away from the sun spans more height within one texel: scale the bias.
    float cosine = std::clamp(std::abs(dot(n, frame_.n)), 0.05f, 1.0f);
    float texel = 1.0f / texelsPerMetre_;
    float bias = texel * (1.0f + 2.0f * std::sqrt(1 - cosine * cosine) / cosine);
    return height_[size_t(y) * size_t(size_) + size_t(x)] > l.z + bias;
}

}  // namespace veduta
