#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/shapes.h"

namespace veduta {
namespace {

// Twice the enclosed volume's divergence integral: for a closed, outward-facing mesh the sum
// of signed tetrahedron volumes is the volume.
double signedVolume(const Mesh &m) {
    double v = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
              c = m.positions[m.indices[3 * t + 2]];
        v += double(dot(a, cross(b, c))) / 6.0;
    }
    return v;
}

TEST(Shapes, ClosedShapesFaceOutwardsWithTheRightVolume) {
    EXPECT_NEAR(signedVolume(makeShape({ShapeKind::Box, {2, 3, 4}})), 24.0, 1e-4);
    // Tessellations are inscribed: a prism or pyramid over a regular n-gon of area
    // (n/2)·sin(2π/n)·r², and a sphere slightly smaller than the true one.
    constexpr int n = 64;
    double polygonArea = n / 2.0 * std::sin(2 * M_PI / n);
    ShapeSpec cylinder{ShapeKind::Cylinder};
    cylinder.radius = 1;
    cylinder.height = 2;
    cylinder.segments = n;
    EXPECT_NEAR(signedVolume(makeShape(cylinder)), 2 * polygonArea, 1e-5);
    ShapeSpec cone = cylinder;
    cone.kind = ShapeKind::Cone;
    cone.height = 3;
    EXPECT_NEAR(signedVolume(makeShape(cone)), polygonArea, 1e-5);
    ShapeSpec sphere{ShapeKind::Sphere};
    sphere.radius = 1;
    sphere.segments = 256;
    sphere.rings = 128;
    double sphereVolume = 4.0 / 3.0 * M_PI;
    EXPECT_LT(signedVolume(makeShape(sphere)), sphereVolume);
    EXPECT_GT(signedVolume(makeShape(sphere)), 0.999 * sphereVolume);
}

TEST(Shapes, TriangleCounts) {
    ShapeSpec sphere{ShapeKind::Sphere};
    sphere.segments = 100;
    sphere.rings = 51;
    EXPECT_EQ(makeShape(sphere).triangleCount(), 10000u);
    EXPECT_EQ(makeShape({ShapeKind::Box}).triangleCount(), 12u);
    EXPECT_EQ(makeShape({ShapeKind::Plane}).triangleCount(), 2u);
}

// Texture coordinates are in metres: on flat faces a triangle's area in uv equals its area in
// space, so a texture said to span 2 m does.
TEST(Shapes, FlatFacesHaveUvsInMetres) {
    for (ShapeKind kind : {ShapeKind::Box, ShapeKind::Plane}) {
        Mesh m = makeShape({kind, {2, 3, 4}});
        ASSERT_EQ(m.uvs.size(), m.vertexCount());
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const uint32_t *idx = &m.indices[3 * t];
            float area = 0.5f *
                length(cross(m.positions[idx[1]] - m.positions[idx[0]], m.positions[idx[2]] - m.positions[idx[0]]));
            Vec2f a = m.uvs[idx[0]], b = m.uvs[idx[1]], c = m.uvs[idx[2]];
            float uvArea = 0.5f * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
            EXPECT_NEAR(uvArea, area, 1e-5f) << "triangle " << t;
        }
    }
}

TEST(Shapes, SidesUnwrapInMetresWithVUp) {
    Mesh box = makeShape({ShapeKind::Box, {2, 3, 4}});
    float maxU = 0, maxV = 0;
    for (size_t v = 0; v < box.vertexCount(); ++v) {
        if (box.normals[v].z != 0) continue;
        maxU = std::max(maxU, box.uvs[v].x);
        maxV = std::max(maxV, box.uvs[v].y);
        EXPECT_FLOAT_EQ(box.uvs[v].y, box.positions[v].z);
    }
    EXPECT_FLOAT_EQ(maxU, 10.0f);  // the perimeter
    EXPECT_FLOAT_EQ(maxV, 4.0f);
    ShapeSpec cylinder{ShapeKind::Cylinder};
    cylinder.radius = 2;
    cylinder.height = 3;
    cylinder.segments = 16;
    Mesh m = makeShape(cylinder);
    maxU = 0;
    for (size_t v = 0; v < m.vertexCount(); ++v) {
        if (std::abs(m.normals[v].z) > 0.5f) {
            EXPECT_FLOAT_EQ(m.uvs[v].x, m.positions[v].x);  // caps: u = x, v = y
            continue;
        }
        maxU = std::max(maxU, m.uvs[v].x);
        EXPECT_FLOAT_EQ(m.uvs[v].y, m.positions[v].z);
    }
    EXPECT_NEAR(maxU, 2 * kPi * 2, 1e-4f);  // the circumference
}

TEST(Shapes, EveryTriangleHasAMaterialSlotAfterSetMaterial) {
    Mesh m = makeShape({ShapeKind::Cone});
    m.setMaterial(3);
    EXPECT_EQ(m.triangleMaterials.size(), m.triangleCount());
}

}  // namespace
}  // namespace veduta
