#include <gtest/gtest.h>

#include <cmath>

#include "scene/shapes.h"
#include "scene/tangents.h"

namespace veduta {
namespace {

// Every tangent is a unit vector orthogonal to its normal and follows the triangle's +u
// direction; sign · cross(n, t) follows +v. Checked at every corner of every triangle.
void expectTangentsFollowUvs(const Mesh &m, const char *what) {
    ASSERT_EQ(m.tangents.size(), m.vertexCount()) << what;
    ASSERT_EQ(m.bitangentSigns.size(), m.vertexCount()) << what;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const uint32_t *idx = &m.indices[3 * t];
        Vec3f e1 = m.positions[idx[1]] - m.positions[idx[0]], e2 = m.positions[idx[2]] - m.positions[idx[0]];
        float du1 = m.uvs[idx[1]].x - m.uvs[idx[0]].x, dv1 = m.uvs[idx[1]].y - m.uvs[idx[0]].y;
        float du2 = m.uvs[idx[2]].x - m.uvs[idx[0]].x, dv2 = m.uvs[idx[2]].y - m.uvs[idx[0]].y;
        float det = du1 * dv2 - du2 * dv1;
        if (std::abs(det) < 1e-6f) continue;
        Vec3f dpdu = normalize((e1 * dv2 - e2 * dv1) / det), dpdv = normalize((e2 * du1 - e1 * du2) / det);
        for (int k = 0; k < 3; ++k) {
            const Vec3f &n = m.normals[idx[k]], &tangent = m.tangents[idx[k]];
            EXPECT_NEAR(length(tangent), 1.0f, 1e-5f) << what;
            EXPECT_NEAR(dot(tangent, n), 0.0f, 1e-5f) << what;
            EXPECT_GT(dot(tangent, dpdu), 0.7f) << what << " triangle " << t;
            EXPECT_GT(dot(cross(n, tangent) * m.bitangentSigns[idx[k]], dpdv), 0.7f) << what << " triangle " << t;
        }
    }
}

TEST(Tangents, FollowTheUvsOfEveryShape) {
    for (ShapeKind kind : {ShapeKind::Box, ShapeKind::Plane, ShapeKind::Sphere, ShapeKind::Cylinder, ShapeKind::Cone}) {
        Mesh m = makeShape({kind, {2, 3, 4}});
        computeTangents(m);
        expectTangentsFollowUvs(m, kind == ShapeKind::Box ? "box" : "shape");
    }
}

TEST(Tangents, PlaneHasTangentEastAndRightHandedFrame) {
    Mesh m = makeShape({ShapeKind::Plane});
    computeTangents(m);
    for (size_t v = 0; v < m.vertexCount(); ++v) {
        EXPECT_NEAR(m.tangents[v].x, 1.0f, 1e-6f);
        EXPECT_EQ(m.bitangentSigns[v], 1.0f);
    }
}

// The box's bottom face has u = x, v = y seen from below: mirrored, so the sign is −1 there.
TEST(Tangents, MirroredUvsGiveANegativeSign) {
    Mesh m = makeShape({ShapeKind::Box});
    computeTangents(m);
    int bottom = 0;
    for (size_t v = 0; v < m.vertexCount(); ++v) {
        bool isBottom = m.normals[v].z < -0.5f;
        EXPECT_EQ(m.bitangentSigns[v], isBottom ? -1.0f : 1.0f) << "vertex " << v;
        bottom += isBottom;
    }
    EXPECT_EQ(bottom, 4);
}

TEST(Tangents, DegenerateUvsFallBackToAnyOrthogonalTangent) {
    Mesh m = makeShape({ShapeKind::Plane});
    m.uvs.assign(m.vertexCount(), Vec2f{0.5f, 0.5f});
    computeTangents(m);
    ASSERT_EQ(m.tangents.size(), m.vertexCount());
    for (size_t v = 0; v < m.vertexCount(); ++v) {
        EXPECT_NEAR(length(m.tangents[v]), 1.0f, 1e-6f);
        EXPECT_NEAR(dot(m.tangents[v], m.normals[v]), 0.0f, 1e-6f);
    }
}

TEST(Tangents, MeshesWithoutUvsOrNormalsGetNone) {
    Mesh noUvs = makeShape({ShapeKind::Plane});
    noUvs.uvs.clear();
    computeTangents(noUvs);
    EXPECT_TRUE(noUvs.tangents.empty());
    EXPECT_TRUE(noUvs.bitangentSigns.empty());
    ShapeSpec faceted{ShapeKind::Cylinder};
    faceted.smooth = false;
    Mesh noNormals = makeShape(faceted);
    computeTangents(noNormals);
    EXPECT_TRUE(noNormals.tangents.empty());
}

TEST(Tangents, AppendClearsThem) {
    Mesh plane = makeShape({ShapeKind::Plane});
    computeTangents(plane);
    Mesh merged = plane;
    merged.append(plane, Transform::translate({2, 0, 0}));
    EXPECT_TRUE(merged.tangents.empty());
    EXPECT_TRUE(merged.bitangentSigns.empty());
    computeTangents(merged);
    expectTangentsFollowUvs(merged, "merged");
}

}  // namespace
}  // namespace veduta
