#include "preview/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace veduta {

namespace {

constexpr float kNothing = -std::numeric_limits<float>::infinity();
constexpr int kRowsPerBand = 64;

// Every placed mesh with its transform, the way the scene draws it.
template <typename F> void forEachPlacedMesh(const RenderScene &scene, F &&f) {
    for (const BakedMesh &m : scene.meshes) f(m.mesh, Transform{});
    for (const Instance &inst : scene.instances) f(scene.prototypes[inst.prototype], inst.objectToWorld);
}

}  // namespace

ShadowMap::ShadowMap(const RenderScene &scene, int size)
    : frame_(Frame::fromNormal(scene.sun.direction)), size_(size), height_(size_t(size) * size_t(size), kNothing) {
    // The map's extent: every vertex, in the sun's frame.
    float uMin = std::numeric_limits<float>::infinity(), vMin = uMin, uMax = -uMin, vMax = -uMin;
    std::vector<std::vector<Vec3f>> placed;
    forEachPlacedMesh(scene, [&](const Mesh &mesh, const Transform &toWorld) {
        std::vector<Vec3f> light(mesh.vertexCount());
        for (size_t i = 0; i < light.size(); ++i) {
            Vec3f p = toWorld.applyPoint(mesh.positions[i]);
            light[i] = {dot(p, frame_.s), dot(p, frame_.t), dot(p, frame_.n)};
            uMin = std::min(uMin, light[i].x), uMax = std::max(uMax, light[i].x);
            vMin = std::min(vMin, light[i].y), vMax = std::max(vMax, light[i].y);
        }
        placed.push_back(std::move(light));
    });
    if (placed.empty()) return;
    originU_ = uMin;
    originV_ = vMin;
    texelsPerMetre_ = float(size) / std::max({uMax - uMin, vMax - vMin, 1e-3f});
    for (std::vector<Vec3f> &light : placed) {
        for (Vec3f &v : light) v = {(v.x - originU_) * texelsPerMetre_, (v.y - originV_) * texelsPerMetre_, v.z};
    }
    // Bands of rows in parallel; each band's texels are written by one thread only.
    int bands = (size + kRowsPerBand - 1) / kRowsPerBand;
    tbb::parallel_for(tbb::blocked_range<int>(0, bands), [&](const tbb::blocked_range<int> &r) {
        for (int band = r.begin(); band != r.end(); ++band) {
            size_t m = 0;
            forEachPlacedMesh(scene, [&](const Mesh &mesh, const Transform &) {
                draw(placed[m++], mesh, band * kRowsPerBand, std::min(size, (band + 1) * kRowsPerBand));
            });
        }
    });
}

void ShadowMap::draw(const std::vector<Vec3f> &v, const Mesh &mesh, int rowBegin, int rowEnd) {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3f &a = v[mesh.indices[3 * t]], &b = v[mesh.indices[3 * t + 1]], &c = v[mesh.indices[3 * t + 2]];
        int x0 = std::max(0, int(std::ceil(std::min({a.x, b.x, c.x}) - 0.5f)));
        int x1 = std::min(size_ - 1, int(std::floor(std::max({a.x, b.x, c.x}) - 0.5f)));
        int y0 = std::max(rowBegin, int(std::ceil(std::min({a.y, b.y, c.y}) - 0.5f)));
        int y1 = std::min(rowEnd - 1, int(std::floor(std::max({a.y, b.y, c.y}) - 0.5f)));
        if (x0 > x1 || y0 > y1) continue;
        float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (area == 0) continue;
        float inv = 1.0f / area;
        for (int y = y0; y <= y1; ++y) {
            float py = float(y) + 0.5f;
            for (int x = x0; x <= x1; ++x) {
                float px = float(x) + 0.5f;
                // Barycentrics; orthographic, so heights interpolate linearly.
                float wb = ((px - a.x) * (c.y - a.y) - (c.x - a.x) * (py - a.y)) * inv;
                float wc = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) * inv;
                float wa = 1 - wb - wc;
                if (std::min({wa, wb, wc}) < 0) continue;
                float &h = height_[size_t(y) * size_t(size_) + size_t(x)];
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
    if (x < 0 || y < 0 || x >= size_ || y >= size_) return false;
    // A surface tilted away from the sun spans more height within one texel: scale the bias.
    float cosine = std::clamp(std::abs(dot(n, frame_.n)), 0.05f, 1.0f);
    float texel = 1.0f / texelsPerMetre_;
    float bias = texel * (1.0f + 2.0f * std::sqrt(1 - cosine * cosine) / cosine);
    return height_[size_t(y) * size_t(size_) + size_t(x)] > l.z + bias;
}

}  // namespace veduta
