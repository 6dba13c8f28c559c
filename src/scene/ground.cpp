#include "scene/ground.h"

namespace veduta {

namespace {

void addVertex(Mesh &m, float x, float y, float height) {
    m.positions.push_back({x, y, height});
    m.normals.push_back({0, 0, 1});
    m.uvs.push_back({x, y});
}

// A quad facing +z from four corners in counter-clockwise order seen from above.
void addQuad(Mesh &m, Vec2f a, Vec2f b, Vec2f c, Vec2f d, float height) {
    uint32_t first = uint32_t(m.positions.size());
    for (Vec2f p : {a, b, c, d}) addVertex(m, p.x, p.y, height);
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(first + i);
}

}  // namespace

Mesh makeGround(float height) {
    constexpr float kInner = 1e3f, kOuter = 1e7f;  // half-sizes; 10⁷ m is the frame's limit
    Mesh m;
    addQuad(m, {-kInner, -kInner}, {kInner, -kInner}, {kInner, kInner}, {-kInner, kInner}, height);
    for (float a = kInner; a < kOuter; a *= 10) {
        float b = a * 10;
        // The ring between the squares of half-sizes a and b, as four trapezoids.
        addQuad(m, {-b, -b}, {b, -b}, {a, -a}, {-a, -a}, height);
        addQuad(m, {b, -b}, {b, b}, {a, a}, {a, -a}, height);
        addQuad(m, {b, b}, {-b, b}, {-a, a}, {a, a}, height);
        addQuad(m, {-b, b}, {-b, -b}, {-a, -a}, {-a, a}, height);
    }
    m.triangleMaterials.assign(m.triangleCount(), 0);
    return m;
}

}  // namespace veduta
