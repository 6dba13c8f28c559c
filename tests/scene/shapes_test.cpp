#include <gtest/gtest.h>

#include <cmath>

#include "scene/shapes.h"

namespace veduta {
namespace {

// Twice the enclosed volume's divergence integral: for a closed, outward-facing mesh the sum
// of signed tetrahedron volumes is the volume.
double signedVolume(const Mesh &m) {
    double v = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]], c = m.positions[m.indices[3 * t + 2]];
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

TEST(Shapes, EveryTriangleHasAMaterialSlotAfterSetMaterial) {
    Mesh m = makeShape({ShapeKind::Cone});
    m.setMaterial(3);
    EXPECT_EQ(m.triangleMaterials.size(), m.triangleCount());
}

}  // namespace
}  // namespace veduta
