#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

#include "geo/tree_models.h"

namespace veduta {
namespace {

constexpr TreeMaterials kMaterials{.bark = 3, .foliage = 7};

bool sameBits(const Mesh &a, const Mesh &b) {
    return a.positions.size() == b.positions.size() && a.indices == b.indices &&
        a.triangleMaterials == b.triangleMaterials &&
        std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3f)) == 0 &&
        std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(Vec3f)) == 0;
}

Vec3f faceNormal(const Mesh &m, size_t t) {
    const uint32_t *i = &m.indices[3 * t];
    return cross(m.positions[i[1]] - m.positions[i[0]], m.positions[i[2]] - m.positions[i[0]]);
}

float angleBetween(const Vec3f &a, const Vec3f &b) { return degrees(std::atan2(length(cross(a, b)), dot(a, b))); }

TEST(TreeModels, TropismAngleIsTheThesisFormula) {
    EXPECT_FLOAT_EQ(tropismAngle({1, 0, 0}, {0, 0, 1}), 45.0f);
    EXPECT_FLOAT_EQ(tropismAngle({0, 0, 1}, {0, 0, 1}), 0.0f);
    EXPECT_FLOAT_EQ(tropismAngle({0, 0, 1}, {0, 0, -1}), 0.0f);
    // |h × t| = 0.5: 90·(1 − 1/1.5) = 30°.
    EXPECT_NEAR(tropismAngle({0, 1, 0}, {0, 0, -0.5f}), 30.0f, 1e-4f);
    // 45° between h and t: |h × t| = sin 45°.
    Vec3f h = normalize(Vec3f{1, 0, 1});
    EXPECT_NEAR(tropismAngle(h, {0, 0, 1}), 90 * (1 - 1 / (1 + std::sqrt(0.5f))), 1e-4f);
}

TEST(TreeModels, TropismTurnsTheHeadingTowardsTButNotPastIt) {
    Vec3f h{1, 0, 0}, t{0, 0, 1};
    Vec3f bent = applyTropism(h, t);
    EXPECT_NEAR(length(bent), 1.0f, 1e-6f);
    EXPECT_NEAR(angleBetween(h, bent), 45.0f, 1e-3f);
    EXPECT_NEAR(angleBetween(bent, t), 45.0f, 1e-3f);  // in the plane of h and t, towards t
    EXPECT_NEAR(bent.y, 0.0f, 1e-6f);
    // 5° from t with a strong t: the formula asks for about 30°, the heading stops at t.
    Vec3f near = normalize(Vec3f{std::sin(radians(5.0f)), 0, std::cos(radians(5.0f))});
    Vec3f strong{0, 0, 5};
    EXPECT_GT(tropismAngle(near, strong), 5.0f);
    EXPECT_NEAR(angleBetween(applyTropism(near, strong), strong), 0.0f, 1e-2f);
    // Along t nothing turns.
    EXPECT_EQ(applyTropism(Vec3f{0, 0, 1}, t), (Vec3f{0, 0, 1}));
}

TEST(TreeModels, AreDeterministicAndVaryWithSeedAndVariant) {
    for (TreeKind kind : {TreeKind::Broadleaf, TreeKind::Conifer}) {
        Mesh a = treeModel(kind, 1, 42, kMaterials);
        EXPECT_TRUE(sameBits(a, treeModel(kind, 1, 42, kMaterials)));
        EXPECT_FALSE(sameBits(a, treeModel(kind, 1, 43, kMaterials)));
        EXPECT_FALSE(sameBits(a, treeModel(kind, 2, 42, kMaterials)));
        EXPECT_TRUE(sameBits(a, treeModel(kind, 1 + kTreeVariants, 42, kMaterials)));
    }
    EXPECT_FALSE(
        sameBits(treeModel(TreeKind::Broadleaf, 0, 1, kMaterials), treeModel(TreeKind::Conifer, 0, 1, kMaterials)));
}

TEST(TreeModels, MixedIsNoTree) { EXPECT_THROW(treeModel(TreeKind::Mixed, 0, 1, kMaterials), std::invalid_argument); }

// Every kind, variant and a few seeds: finite, unit normals, faces outward (their normals agree
// with the vertex normals), the two materials, the triangle budget, height 1 standing on the
// origin.
TEST(TreeModels, MeshesAreValid) {
    for (TreeKind kind : {TreeKind::Broadleaf, TreeKind::Conifer}) {
        for (uint32_t variant = 0; variant < kTreeVariants; ++variant) {
            for (uint32_t seed = 0; seed < 6; ++seed) {
                SCOPED_TRACE(::testing::Message()
                             << "kind " << int(kind) << " variant " << variant << " seed " << seed);
                Mesh m = treeModel(kind, variant, seed, kMaterials);
                ASSERT_GT(m.triangleCount(), 300u);
                EXPECT_LE(m.triangleCount(), kTreeTriangleBudget);
                ASSERT_EQ(m.normals.size(), m.positions.size());
                ASSERT_EQ(m.uvs.size(), m.positions.size());
                ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
                float top = -1, bottom = 1, reach = 0;
                for (size_t v = 0; v < m.vertexCount(); ++v) {
                    const Vec3f &p = m.positions[v];
                    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
                    ASSERT_NEAR(length(m.normals[v]), 1.0f, 1e-4f);
                    top = std::max(top, p.z);
                    bottom = std::min(bottom, p.z);
                    reach = std::max(reach, std::hypot(p.x, p.y));
                }
                EXPECT_FLOAT_EQ(top, 1.0f);
                EXPECT_LE(bottom, 0.0f);  // the trunk reaches into the ground a little
                EXPECT_GT(bottom, -0.02f);
                EXPECT_GT(reach, 0.1f);
                EXPECT_LT(reach, 0.7f);
                std::map<MaterialId, size_t> perMaterial;
                for (size_t t = 0; t < m.triangleCount(); ++t) {
                    ++perMaterial[m.triangleMaterials[t]];
                    Vec3f n = faceNormal(m, t);
                    ASSERT_GT(length(n), 0.0f) << "triangle " << t;
                    for (int k = 0; k < 3; ++k) {
                        uint32_t v = m.indices[3 * t + k];
                        ASSERT_LT(v, m.vertexCount());
                        EXPECT_GT(dot(n, m.normals[v]), 0.0f) << "triangle " << t;
                    }
                }
                EXPECT_EQ(perMaterial.size(), 2u);
                EXPECT_GT(perMaterial[kMaterials.bark], 0u);
                EXPECT_GT(perMaterial[kMaterials.foliage], 0u);
            }
        }
    }
}

// The foliage blobs are closed: every edge of a foliage triangle is met once in each direction.
TEST(TreeModels, FoliageIsClosed) {
    for (TreeKind kind : {TreeKind::Broadleaf, TreeKind::Conifer}) {
        Mesh m = treeModel(kind, 0, 5, kMaterials);
        std::map<std::pair<uint32_t, uint32_t>, int> edges;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            if (m.triangleMaterials[t] != kMaterials.foliage) continue;
            for (int k = 0; k < 3; ++k) ++edges[{m.indices[3 * t + k], m.indices[3 * t + (k + 1) % 3]}];
        }
        ASSERT_FALSE(edges.empty());
        for (const auto &[edge, count] : edges) {
            EXPECT_EQ(count, 1);
            EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
        }
    }
}

// The mean distance of the foliage from the trunk in the lower and the upper third of the
// crown's height.
std::pair<float, float> foliageSpread(const Mesh &m) {
    float zLow = 1, zHigh = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != kMaterials.foliage) continue;
        zLow = std::min(zLow, m.positions[m.indices[3 * t]].z);
        zHigh = std::max(zHigh, m.positions[m.indices[3 * t]].z);
    }
    float third = (zHigh - zLow) / 3;
    float sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != kMaterials.foliage) continue;
        const Vec3f &p = m.positions[m.indices[3 * t]];
        int band = p.z < zLow + third ? 0 : (p.z > zHigh - third ? 1 : -1);
        if (band < 0) continue;
        sum[band] += std::hypot(p.x, p.y);
        ++count[band];
    }
    return {sum[0] / float(std::max(count[0], 1)), sum[1] / float(std::max(count[1], 1))};
}

TEST(TreeModels, ConifersAreConesAndBroadleavesCarryTheirCrownsHigh) {
    for (uint32_t variant = 0; variant < kTreeVariants; ++variant) {
        auto [coniferLow, coniferHigh] = foliageSpread(treeModel(TreeKind::Conifer, variant, 9, kMaterials));
        EXPECT_GT(coniferLow, 1.5f * coniferHigh) << "variant " << variant;
        // A broadleaf's lower third is mostly trunk: less foliage there than in the crown.
        Mesh broad = treeModel(TreeKind::Broadleaf, variant, 9, kMaterials);
        size_t low = 0, high = 0;
        for (size_t t = 0; t < broad.triangleCount(); ++t) {
            if (broad.triangleMaterials[t] != kMaterials.foliage) continue;
            float z = broad.positions[broad.indices[3 * t]].z;
            low += z < 1.0f / 3;
            high += z > 2.0f / 3;
        }
        EXPECT_LT(low, high) << "variant " << variant;
    }
}

}  // namespace
}  // namespace veduta
