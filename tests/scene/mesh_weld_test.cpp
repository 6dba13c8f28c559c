// weldVertices: vertices meant to be one (the same place, normal and texture coordinates on a
// fine grid) become one, the first of them kept, in the order they come.
#include "scene/mesh.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>

namespace veduta {
namespace {

Mesh quadOfTwoTriangles() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
    m.normals.assign(6, {0, 0, 1});
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}, {0, 0}};
    m.indices = {0, 1, 2, 3, 4, 5};
    m.triangleMaterials = {3, 4};
    return m;
}

TEST(WeldVertices, SharedCornersBecomeOneInTheOrderTheyCome) {
    Mesh welded = weldVertices(quadOfTwoTriangles());
    ASSERT_EQ(welded.positions.size(), 4u);
    EXPECT_EQ(welded.positions[3], Vec3f(0, 1, 0));
    EXPECT_EQ(welded.indices, (std::vector<uint32_t>{0, 1, 2, 2, 3, 0}));
    EXPECT_EQ(welded.triangleMaterials, (std::vector<MaterialId>{3, 4}));
    EXPECT_EQ(welded.normals.size(), 4u);
    EXPECT_EQ(welded.uvs.size(), 4u);
}

TEST(WeldVertices, OnlyWhatIsMeantToBeOneFallsTogether) {
    Mesh m = quadOfTwoTriangles();
    m.positions[3] = {1, 1.00002f, 0};  // a rounding apart: one vertex
    EXPECT_EQ(weldVertices(m).positions.size(), 4u);
    m.positions[3] = {1, 1.001f, 0};  // a millimetre apart: two
    EXPECT_EQ(weldVertices(m).positions.size(), 5u);
    m = quadOfTwoTriangles();
    m.normals[5] = {0, 1, 0};  // a crease
    EXPECT_EQ(weldVertices(m).positions.size(), 5u);
    m = quadOfTwoTriangles();
    m.uvs[3] = {2, 1};  // a texture seam
    EXPECT_EQ(weldVertices(m).positions.size(), 5u);
}

// Many copies of a few hundred vertices in a scrambled order: each vertex goes to the first of
// its copies, as a search from the start finds it.
TEST(WeldVertices, EachVertexGoesToTheFirstOfItsCopies) {
    Mesh m;
    uint32_t state = 12345;
    auto next = [&state] { return state = state * 1664525u + 1013904223u; };
    for (int v = 0; v < 30000; ++v) {
        uint32_t which = next() % 500;
        m.positions.push_back({float(which % 10), float(which / 10 % 10), float(which / 100) * 0.5f});
    }
    for (size_t v = 0; v + 2 < m.positions.size(); v += 3)
        m.indices.insert(m.indices.end(), {uint32_t(v), uint32_t(v + 1), uint32_t(v + 2)});
    m.triangleMaterials.assign(m.triangleCount(), 0);
    Mesh welded = weldVertices(m);
    std::map<std::tuple<float, float, float>, uint32_t> first;
    std::vector<Vec3f> expected;
    for (const Vec3f &p : m.positions)
        if (first.emplace(std::tuple(p.x, p.y, p.z), uint32_t(expected.size())).second) expected.push_back(p);
    EXPECT_EQ(welded.positions, expected);
    for (size_t i = 0; i < m.indices.size(); ++i) {
        const Vec3f &p = m.positions[m.indices[i]];
        ASSERT_EQ(welded.indices[i], first.at(std::tuple(p.x, p.y, p.z))) << i;
    }
}

}  // namespace
}  // namespace veduta
