#include "scene/shapes.h"

#include <cmath>

namespace veduta {

namespace {

// Adds a quad a-b-c-d (counter-clockwise seen from outside) as two triangles.
void addQuad(Mesh &m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

Mesh makeBox(Vec3f size) {
    Mesh m;
    Vec3f lo{-size.x / 2, -size.y / 2, 0}, hi{size.x / 2, size.y / 2, size.z};
    for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    addQuad(m, 0, 2, 3, 1);  // bottom
    addQuad(m, 4, 5, 7, 6);  // top
    addQuad(m, 0, 1, 5, 4);  // south
    addQuad(m, 2, 6, 7, 3);  // north
    addQuad(m, 0, 4, 6, 2);  // west
    addQuad(m, 1, 3, 7, 5);  // east
    return m;
}

Mesh makePlane(Vec3f size) {
    Mesh m;
    m.positions = {{-size.x / 2, -size.y / 2, 0}, {size.x / 2, -size.y / 2, 0}, {size.x / 2, size.y / 2, 0},
                   {-size.x / 2, size.y / 2, 0}};
    m.normals.assign(4, {0, 0, 1});
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    addQuad(m, 0, 1, 2, 3);
    return m;
}

Mesh makeSphere(float radius, int segments, int rings) {
    Mesh m;
    for (int r = 0; r <= rings; ++r) {
        float theta = kPi * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            float phi = 2 * kPi * float(s) / float(segments);
            Vec3f n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
            m.positions.push_back(n * radius);
            m.normals.push_back(n);
            m.uvs.push_back({float(s) / float(segments), 1 - float(r) / float(rings)});
        }
    }
    auto at = [&](int r, int s) { return uint32_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            // Rings run from the north pole down; the pole rows degenerate to triangles.
            if (r != 0) m.indices.insert(m.indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
            if (r != rings - 1) m.indices.insert(m.indices.end(), {at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
        }
    }
    return m;
}

// A cylinder whose top radius may differ from its bottom one; a cone has top radius 0.
Mesh makeFrustum(float bottomRadius, float topRadius, float height, int segments, bool smooth) {
    Mesh m;
    float slope = (bottomRadius - topRadius) / height;
    auto ring = [&](int s) {
        float phi = 2 * kPi * float(s % segments) / float(segments);
        return Vec3f{std::cos(phi), std::sin(phi), 0};
    };
    // Side: with smooth shading one shared vertex pair per segment edge; faceted sides get
    // their own vertices and no normals (flat shading needs none).
    for (int s = 0; s < segments; ++s) {
        Vec3f d0 = ring(s), d1 = ring(s + 1);
        auto base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {d0 * bottomRadius, d1 * bottomRadius,
                                               d1 * topRadius + Vec3f{0, 0, height}, d0 * topRadius + Vec3f{0, 0, height}});
        if (smooth) {
            Vec3f n0 = normalize(d0 + Vec3f{0, 0, slope}), n1 = normalize(d1 + Vec3f{0, 0, slope});
            m.normals.insert(m.normals.end(), {n0, n1, n1, n0});
        }
        if (topRadius > 0) {
            addQuad(m, base, base + 1, base + 2, base + 3);
        } else {
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
        }
    }
    auto addCap = [&](float radius, float z, bool up) {
        auto centre = uint32_t(m.positions.size());
        m.positions.push_back({0, 0, z});
        for (int s = 0; s < segments; ++s) m.positions.push_back(ring(s) * radius + Vec3f{0, 0, z});
        if (smooth) m.normals.insert(m.normals.end(), size_t(segments) + 1, Vec3f{0, 0, up ? 1.0f : -1.0f});
        for (int s = 0; s < segments; ++s) {
            uint32_t a = centre + 1 + uint32_t(s), b = centre + 1 + uint32_t((s + 1) % segments);
            if (up) {
                m.indices.insert(m.indices.end(), {centre, a, b});
            } else {
                m.indices.insert(m.indices.end(), {centre, b, a});
            }
        }
    };
    addCap(bottomRadius, 0, false);
    if (topRadius > 0) addCap(topRadius, height, true);
    return m;
}

}  // namespace

Mesh makeShape(const ShapeSpec &spec) {
    switch (spec.kind) {
    case ShapeKind::Box: return makeBox(spec.size);
    case ShapeKind::Plane: return makePlane(spec.size);
    case ShapeKind::Sphere: return makeSphere(spec.radius, spec.segments, spec.rings);
    case ShapeKind::Cylinder: return makeFrustum(spec.radius, spec.radius, spec.height, spec.segments, spec.smooth);
    case ShapeKind::Cone: return makeFrustum(spec.radius, 0, spec.height, spec.segments, spec.smooth);
    }
    return {};
}

}  // namespace veduta
