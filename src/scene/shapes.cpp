#include "scene/shapes.h"

#include "scene/ground.h"

#include <cmath>

namespace veduta {

namespace {

// Adds a quad a-b-c-d (counter-clockwise seen from outside) as two triangles.
void addQuad(Mesh &m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

// A horizontal rectangle at height z facing up or down, with u = x and v = y in metres.
void addHorizontalFace(Mesh &m, float halfX, float halfY, float z, bool up) {
    auto base = uint32_t(m.positions.size());
    for (Vec2f c : {Vec2f{-halfX, -halfY}, Vec2f{halfX, -halfY}, Vec2f{halfX, halfY}, Vec2f{-halfX, halfY}}) {
        m.positions.push_back({c.x, c.y, z});
        m.normals.push_back({0, 0, up ? 1.0f : -1.0f});
        m.uvs.push_back(c);
    }
    if (up) {
        addQuad(m, base, base + 1, base + 2, base + 3);
    } else {
        addQuad(m, base, base + 3, base + 2, base + 1);
    }
}

// Each face has its own vertices, normals and uvs, so that normal maps have tangents to work
// with; the normals are the face normals, so the box shades flat as before. The sides unwrap
// counter-clockwise seen from above, which is left to right seen from outside: u runs on
// round the corners (as on a cylinder) and v is the height, both in metres.
Mesh makeBox(Vec3f size) {
    Mesh m;
    float hx = size.x / 2, hy = size.y / 2;
    struct Side {
        Vec3f left, right, normal;  // lower corners seen from outside
    };
    const Side sides[] = {{{-hx, -hy, 0}, {hx, -hy, 0}, {0, -1, 0}},
                          {{hx, -hy, 0}, {hx, hy, 0}, {1, 0, 0}},
                          {{hx, hy, 0}, {-hx, hy, 0}, {0, 1, 0}},
                          {{-hx, hy, 0}, {-hx, -hy, 0}, {-1, 0, 0}}};
    Vec3f up{0, 0, size.z};
    float u = 0;
    for (const Side &side : sides) {
        auto base = uint32_t(m.positions.size());
        float width = length(side.right - side.left);
        m.positions.insert(m.positions.end(), {side.left, side.right, side.right + up, side.left + up});
        m.normals.insert(m.normals.end(), 4, side.normal);
        m.uvs.insert(m.uvs.end(), {{u, 0}, {u + width, 0}, {u + width, size.z}, {u, size.z}});
        addQuad(m, base, base + 1, base + 2, base + 3);
        u += width;
    }
    addHorizontalFace(m, hx, hy, size.z, true);
    addHorizontalFace(m, hx, hy, 0, false);
    return m;
}

// uvs in metres from the corner at (−x, −y), so that a material's texture scale is in metres.
Mesh makePlane(Vec3f size) {
    Mesh m;
    m.positions = {{-size.x / 2, -size.y / 2, 0},
                   {size.x / 2, -size.y / 2, 0},
                   {size.x / 2, size.y / 2, 0},
                   {-size.x / 2, size.y / 2, 0}};
    m.normals.assign(4, {0, 0, 1});
    m.uvs = {{0, 0}, {size.x, 0}, {size.x, size.y}, {0, size.y}};
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
            // Metres: arc length along the equator and up the meridian from the south pole.
            m.uvs.push_back({radius * phi, radius * (kPi - theta)});
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

// A cylinder whose top radius may differ from its bottom one; a cone has top radius 0. uvs in
// metres: on the side u is the arc length round the bottom edge and v the height, on the caps
// u = x and v = y.
Mesh makeFrustum(float bottomRadius, float topRadius, float height, int segments, bool smooth) {
    Mesh m;
    float slope = (bottomRadius - topRadius) / height;
    float arcPerSegment = 2 * kPi * bottomRadius / float(segments);
    auto ring = [&](int s) {
        float phi = 2 * kPi * float(s % segments) / float(segments);
        return Vec3f{std::cos(phi), std::sin(phi), 0};
    };
    // Side: with smooth shading one shared vertex pair per segment edge; faceted sides get
    // their own vertices and no normals (flat shading needs none).
    for (int s = 0; s < segments; ++s) {
        Vec3f d0 = ring(s), d1 = ring(s + 1);
        auto base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(),
                           {d0 * bottomRadius, d1 * bottomRadius, d1 * topRadius + Vec3f{0, 0, height},
                            d0 * topRadius + Vec3f{0, 0, height}});
        if (smooth) {
            Vec3f n0 = normalize(d0 + Vec3f{0, 0, slope}), n1 = normalize(d1 + Vec3f{0, 0, slope});
            m.normals.insert(m.normals.end(), {n0, n1, n1, n0});
        }
        float u0 = arcPerSegment * float(s), u1 = u0 + arcPerSegment;
        // A cone's apex sits over the middle of its segment, which shears the texture least.
        float apexU = topRadius > 0 ? u1 : 0.5f * (u0 + u1);
        m.uvs.insert(m.uvs.end(), {{u0, 0}, {u1, 0}, {apexU, height}, {u0, height}});
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
        m.uvs.push_back({0, 0});
        for (int s = 0; s < segments; ++s) m.uvs.push_back({ring(s).x * radius, ring(s).y * radius});
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
    case ShapeKind::Ground: return makeGround(spec.height);
    case ShapeKind::Sphere: return makeSphere(spec.radius, spec.segments, spec.rings);
    case ShapeKind::Cylinder: return makeFrustum(spec.radius, spec.radius, spec.height, spec.segments, spec.smooth);
    case ShapeKind::Cone: return makeFrustum(spec.radius, 0, spec.height, spec.segments, spec.smooth);
    }
    return {};
}

}  // namespace veduta
