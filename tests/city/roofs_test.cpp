#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "city/roof_choice.h"
#include "city/roofs.h"

namespace veduta {
namespace {

// T7's building: 20 m along the street (edge 0, facing south), 12 m deep.
Footprint rectangle(std::vector<bool> streetEdges) { return {{{0, 0}, {20, 0}, {20, 12}, {0, 12}}, streetEdges, 0}; }

// An L whose arms are 24 m long and 12 m wide, with no street.
Footprint lShape() {
    return {{{0, 0}, {24, 0}, {24, 12}, {12, 12}, {12, 24}, {0, 24}}, std::vector<bool>(6, false), 0};
}

Vec3f corner(const Mesh &m, size_t triangle, int k) { return m.positions[m.indices[3 * triangle + size_t(k)]]; }

Vec3f geometricNormal(const Mesh &m, size_t t) {
    return normalize(cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0)));
}

float area(const Mesh &m, size_t t) {
    return 0.5f * length(cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0)));
}

float uvArea(const Mesh &m, size_t t) {
    const uint32_t *idx = &m.indices[3 * t];
    Vec2f a = m.uvs[idx[0]], b = m.uvs[idx[1]], c = m.uvs[idx[2]];
    return 0.5f * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

Vec3f centroid(const Mesh &m, size_t t) { return (corner(m, t, 0) + corner(m, t, 1) + corner(m, t, 2)) / 3; }

size_t countSurface(const Mesh &m, RoofSurface surface) {
    return size_t(std::count(m.triangleMaterials.begin(), m.triangleMaterials.end(), MaterialId(surface)));
}

// Every triangle has area, a material, and at each corner the normal of its own face.
void expectWellFormed(const Mesh &m) {
    ASSERT_EQ(m.normals.size(), m.vertexCount());
    ASSERT_EQ(m.uvs.size(), m.vertexCount());
    ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        EXPECT_GT(area(m, t), 1e-3f) << "triangle " << t;
        Vec3f n = geometricNormal(m, t);
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(dot(m.normals[m.indices[3 * t + size_t(k)]], n), 0.9999f) << "triangle " << t;
    }
}

// The roof covering's texture is one tile per metre both ways: flat faces keep their areas in uv.
void expectUvsInMetres(const Mesh &m) {
    for (size_t t = 0; t < m.triangleCount(); ++t) EXPECT_NEAR(uvArea(m, t), area(m, t), 1e-3f) << "triangle " << t;
}

TEST(Roofs, ThesisRoofType) {
    EXPECT_EQ(thesisRoofType(rectangle({true, false, false, false})), RoofType::Gable);
    EXPECT_EQ(thesisRoofType(rectangle({true, true, false, false})), RoofType::Mansard);
    EXPECT_EQ(thesisRoofType(rectangle({false, false, false, false})), RoofType::Mansard);
    Footprint l = lShape();
    l.streetEdges[0] = true;
    EXPECT_EQ(thesisRoofType(l), RoofType::Mansard);
    // A parallelogram has four corners but not right ones.
    Footprint slanted{{{0, 0}, {20, 0}, {23, 12}, {3, 12}}, {true, false, false, false}, 0};
    EXPECT_EQ(thesisRoofType(slanted), RoofType::Mansard);
    // Turned by 30°, the rectangle's angles are right within float rounding.
    Footprint turned = rectangle({true, false, false, false});
    Transform rotation = Transform::rotate(2, 30);
    for (Vec2f &p : turned.points) {
        Vec3f q = rotation.applyPoint(lift(p, 0));
        p = {q.x, q.y};
    }
    EXPECT_EQ(thesisRoofType(turned), RoofType::Gable);
}

TEST(Roofs, MansardOverAnLShape) {
    Footprint l = lShape();
    MansardRoof roof = mansardRoof(l, 15, 3, 2);
    expectWellFormed(roof.mesh);
    expectUvsInMetres(roof.mesh);
    EXPECT_EQ(roof.inset, 2);
    const std::vector<std::pair<float, float>> expectedTop{{2, 2}, {22, 2}, {22, 10}, {10, 10}, {10, 22}, {2, 22}};
    ASSERT_EQ(roof.top.size(), 6u);
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_NEAR(roof.top[i].x, expectedTop[i].first, 1e-5f) << i;
        EXPECT_NEAR(roof.top[i].y, expectedTop[i].second, 1e-5f) << i;
    }
    EXPECT_TRUE(liesInside(roof.top, l.points));
    EXPECT_EQ(roof.mesh.triangleCount(), 6u * 2 + 4);
    EXPECT_EQ(countSurface(roof.mesh, RoofCovering), roof.mesh.triangleCount());
    float topArea = 0;
    size_t topTriangles = 0;
    for (size_t t = 0; t < roof.mesh.triangleCount(); ++t) {
        Vec3f n = geometricNormal(roof.mesh, t);
        if (n.z > 0.9999f) {
            ++topTriangles;
            topArea += area(roof.mesh, t);
            EXPECT_EQ(centroid(roof.mesh, t).z, 18);
            continue;
        }
        // Side t / 2 slopes up from footprint edge t / 2 towards the inside.
        EXPECT_GT(n.z, 0) << "triangle " << t;
        EXPECT_GT(dot(n, l.outwardNormal(t / 2)), 0) << "triangle " << t;
    }
    EXPECT_EQ(topTriangles, 4u);
    EXPECT_NEAR(topArea, 20 * 8 + 8 * 12, 1e-3f);
}

TEST(Roofs, MansardSideQuadsRunLowerLeftLowerRightUpperRightUpperLeft) {
    Footprint l = lShape();
    MansardRoof roof = mansardRoof(l, 15, 3, 2);
    for (size_t e = 0; e < 6; ++e) {
        // The first side quad's triangles are (ll, lr, ur) and (ll, ur, ul).
        const Mesh &m = roof.mesh;
        EXPECT_EQ(corner(m, 2 * e, 0), lift(l.edgeStart(e), 15)) << e;
        EXPECT_EQ(corner(m, 2 * e, 1), lift(l.edgeEnd(e), 15)) << e;
        EXPECT_EQ(corner(m, 2 * e, 2), lift(roof.top[(e + 1) % 6], 18)) << e;
        EXPECT_EQ(corner(m, 2 * e + 1, 2), lift(roof.top[e], 18)) << e;
    }
}

TEST(Roofs, MansardHalvesAnInsetTheFootprintCannotTake) {
    // 10 m from both sides of a 12 m arm turns the arm's ends inside out; 5 m leaves it 2 m.
    MansardRoof roof = mansardRoof(lShape(), 15, 3, 10);
    EXPECT_EQ(roof.inset, 5);
    const std::vector<std::pair<float, float>> expectedTop{{5, 5}, {19, 5}, {19, 7}, {7, 7}, {7, 19}, {5, 19}};
    ASSERT_EQ(roof.top.size(), 6u);
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_NEAR(roof.top[i].x, expectedTop[i].first, 1e-5f) << i;
        EXPECT_NEAR(roof.top[i].y, expectedTop[i].second, 1e-5f) << i;
    }
    expectWellFormed(roof.mesh);
    // Half the arm's width, 6 m, shrinks the arm's end to nothing: 12 m is halved twice.
    EXPECT_EQ(mansardRoof(lShape(), 15, 3, 12).inset, 3);
}

TEST(Roofs, MansardInsetStaysInsideASharpNotch) {
    // A V cut 9 m deep and 1 m wide into a 20 × 10 block: its tip's corner moves inset / sin(3.18°),
    // about 18 × the inset, so it stays above the bottom's inset line only for insets below 1/19 m.
    Footprint notched{
        {{0, 0}, {20, 0}, {20, 10}, {10.5f, 10}, {10, 1}, {9.5f, 10}, {0, 10}}, std::vector<bool>(7, false), 0};
    MansardRoof roof = mansardRoof(notched, 15, 3, 1);
    EXPECT_EQ(roof.inset, 1.0f / 32);
    EXPECT_TRUE(liesInside(roof.top, notched.points));
    expectWellFormed(roof.mesh);
}

TEST(Roofs, MansardGivesUpAsAFlatRoofAtTheEaves) {
    Footprint l = lShape();
    // 10 km halved kMansardInsetHalvings times is still 39 m.
    for (float inset : {1e4f, 0.0f}) {
        MansardRoof roof = mansardRoof(l, 15, 3, inset);
        expectWellFormed(roof.mesh);
        EXPECT_EQ(roof.inset, 0);
        ASSERT_EQ(roof.top.size(), l.points.size());
        for (size_t i = 0; i < l.points.size(); ++i) EXPECT_EQ(lift(roof.top[i], 0), lift(l.points[i], 0));
        EXPECT_EQ(roof.mesh.triangleCount(), 4u);
        for (const Vec3f &p : roof.mesh.positions) EXPECT_EQ(p.z, 15);
        for (const Vec3f &n : roof.mesh.normals) EXPECT_EQ(n, Vec3f(0, 0, 1));
    }
}

}  // namespace
}  // namespace veduta
