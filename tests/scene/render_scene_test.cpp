#include <gtest/gtest.h>

#include "scene/render_scene.h"
#include "scene/shapes.h"

namespace veduta {
namespace {

TEST(RenderSceneBuilder, BakesPrototypesPlacedOnceAndSharesTheRest) {
    RenderSceneBuilder builder;
    MaterialId red = builder.addMaterial(Material::lambertian("red", Vec3f(0.9f, 0.1f, 0.1f)));
    PrototypeId once = builder.addPrototype(makeShape({}));
    PrototypeId twice = builder.addPrototype(makeShape({ShapeKind::Sphere}));
    builder.addPrototype(makeShape({}));  // never placed
    builder.addInstance({Transform::translate({5, 0, 0}), once, red, 7});
    builder.addInstance({Transform::translate({0, 5, 0}), twice, kNoMaterial, 8});
    builder.addInstance({Transform::translate({0, 9, 0}), twice, kNoMaterial, 9});
    RenderScene scene = std::move(builder).build();

    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.meshes[0].objectId, 7u);
    EXPECT_EQ(scene.meshes[0].mesh.triangleMaterials[0], red);
    EXPECT_FLOAT_EQ(scene.meshes[0].mesh.positions[0].x, 4.5f);  // box corner moved by +5
    ASSERT_EQ(scene.prototypes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].prototype, 0u);
    EXPECT_EQ(scene.instances[1].objectId, 9u);
    EXPECT_EQ(scene.effectiveTriangleCount(), 12u + 2u * scene.prototypes[0].triangleCount());
}

TEST(Mesh, AppendingFacetedToSmoothKeepsBothLooks) {
    Mesh smooth = makeShape({ShapeKind::Sphere});
    Mesh merged;
    merged.append(smooth, Transform{});
    ShapeSpec prism{ShapeKind::Cylinder};
    prism.smooth = false;
    merged.append(makeShape(prism), Transform::translate({3, 0, 0}));
    ASSERT_EQ(merged.normals.size(), merged.positions.size());
    // The prism's triangles got face normals: each is perpendicular to its triangle.
    size_t t = smooth.triangleCount();
    const uint32_t *idx = &merged.indices[3 * t];
    Vec3f n = normalize(cross(merged.positions[idx[1]] - merged.positions[idx[0]],
                              merged.positions[idx[2]] - merged.positions[idx[0]]));
    EXPECT_NEAR(dot(n, merged.normals[idx[0]]), 1.0f, 1e-6f);
}

TEST(Mesh, AppendingAMeshWithoutTrianglesChangesNothing) {
    Mesh smooth = makeShape({ShapeKind::Sphere});
    Mesh merged = smooth;
    Mesh pointsOnly;
    pointsOnly.positions = {{0, 0, 0}, {1, 0, 0}};
    merged.append(pointsOnly, Transform{});
    EXPECT_EQ(merged.positions.size(), smooth.positions.size());
    EXPECT_EQ(merged.normals.size(), smooth.normals.size());
}

TEST(Mesh, MirroringTransformKeepsTrianglesFacingOut) {
    Mesh box = makeShape({});
    Mesh mirrored;
    mirrored.append(box, Transform::scale({-1, 1, 1}));
    // Top face: its normal must still point up.
    for (size_t t = 0; t < mirrored.triangleCount(); ++t) {
        const uint32_t *idx = &mirrored.indices[3 * t];
        Vec3f a = mirrored.positions[idx[0]], b = mirrored.positions[idx[1]], c = mirrored.positions[idx[2]];
        Vec3f centre = (a + b + c) / 3.0f - Vec3f{0, 0, 0.5f};
        EXPECT_GT(dot(cross(b - a, c - a), centre), 0) << "triangle " << t << " faces inwards";
    }
}

}  // namespace
}  // namespace veduta
