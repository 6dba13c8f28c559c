#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "geo/tree_models.h"
#include "geo/tree_placement.h"

namespace veduta {
namespace {

std::vector<Vec2f> square(float x0, float y0, float size) {
    return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

// A U: two 60 m wide arms and a base, the notch 80 m wide and 150 m deep.
const std::vector<Vec2f> kU = {{0, 0}, {200, 0}, {200, 200}, {140, 200}, {140, 50}, {60, 50}, {60, 200}, {0, 200}};
bool insideU(Vec2f p) {
    bool inBox = p.x > 0 && p.x < 200 && p.y > 0 && p.y < 200;
    bool inNotch = p.x >= 60 && p.x <= 140 && p.y >= 50;
    return inBox && !inNotch;
}

TreeStand forest(TreeKind kind = TreeKind::Mixed) { return treeStand(LandClass::Forest, kind); }

std::vector<PlacedTree> plantedArea(const std::vector<Vec2f> &ring, const TreeStand &stand, uint32_t seed,
                                    uint32_t objectId) {
    TreeSet set;
    plantArea(set, ring, stand, seed, objectId);
    return set.trees;
}

bool sameTrees(const std::vector<PlacedTree> &a, const std::vector<PlacedTree> &b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].position.x != b[i].position.x || a[i].position.y != b[i].position.y || a[i].kind != b[i].kind ||
            a[i].variant != b[i].variant || a[i].height != b[i].height || a[i].rotation != b[i].rotation ||
            a[i].widthScale != b[i].widthScale) {
            return false;
        }
    }
    return true;
}

float minimumDistance(const std::vector<PlacedTree> &trees) {
    float best = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < trees.size(); ++i) {
        for (size_t j = i + 1; j < trees.size(); ++j) {
            Vec2f d = trees[i].position - trees[j].position;
            best = std::min(best, std::sqrt(dot(d, d)));
        }
    }
    return best;
}

TEST(TreePlacement, StandsPerLandClass) {
    EXPECT_FLOAT_EQ(treeStand(LandClass::Forest, TreeKind::Conifer).spacing, 5.5f);
    EXPECT_EQ(treeStand(LandClass::Forest, TreeKind::Conifer).kind, TreeKind::Conifer);
    EXPECT_FLOAT_EQ(treeStand(LandClass::Shrubs, TreeKind::Mixed).spacing, 3.0f);
    EXPECT_FLOAT_EQ(treeStand(LandClass::TreeRow, TreeKind::Mixed).spacing, 9.0f);
    EXPECT_EQ(treeStand(LandClass::Hedge, TreeKind::Conifer).kind, TreeKind::Broadleaf);
    EXPECT_FLOAT_EQ(treeStand(LandClass::Road, TreeKind::Mixed).spacing, 0.0f);
}

TEST(TreePlacement, AreaIsDeterministicAndVariesWithSeedAndObject) {
    std::vector<PlacedTree> a = plantedArea(kU, forest(), 7, 100);
    ASSERT_GT(a.size(), 500u);
    EXPECT_TRUE(sameTrees(a, plantedArea(kU, forest(), 7, 100)));
    EXPECT_FALSE(sameTrees(a, plantedArea(kU, forest(), 8, 100)));
    EXPECT_FALSE(sameTrees(a, plantedArea(kU, forest(), 7, 101)));
    // Where the outline starts and which way it runs does not matter.
    std::vector<Vec2f> turned(kU.rbegin(), kU.rend());
    std::rotate(turned.begin(), turned.begin() + 3, turned.end());
    EXPECT_TRUE(sameTrees(a, plantedArea(turned, forest(), 7, 100)));
}

TEST(TreePlacement, AreaKeepsTheDistanceAndStaysInsideAConcaveOutline) {
    for (float spacing : {3.0f, 5.5f}) {
        TreeStand stand = forest();
        stand.spacing = spacing;
        std::vector<PlacedTree> trees = plantedArea(kU, stand, 3, 9);
        EXPECT_GE(minimumDistance(trees), spacing);
        for (const PlacedTree &t : trees) EXPECT_TRUE(insideU(t.position)) << t.position.x << " " << t.position.y;
    }
}

// Dart throwing leaves no holes: every point of the area lies within two spacings of a tree,
// and the density is that of a well-filled Poisson-disk set (Bridson's reaches about 0.7 of
// the hexagonal packing; random sequential adsorption saturates at 0.547·4/π ≈ 0.70 r⁻²).
TEST(TreePlacement, AreaIsFilledEvenly) {
    const float spacing = 5;
    TreeStand stand = forest();
    stand.spacing = spacing;
    std::vector<PlacedTree> trees = plantedArea(square(-130, 40, 400), stand, 11, 2);
    double perSquareSpacing = double(trees.size()) * spacing * spacing / (400.0 * 400.0);
    EXPECT_GT(perSquareSpacing, 0.62);
    EXPECT_LT(perSquareSpacing, 2 / std::sqrt(3.0));  // the hexagonal packing, which nothing exceeds
    // Holes: the nearest tree to each probe of a 2 m lattice, through a coarse bucket grid.
    const float bucket = 10;
    std::vector<std::vector<Vec2f>> buckets(40 * 40);
    for (const PlacedTree &t : trees) {
        int bx = std::clamp(int((t.position.x + 130) / bucket), 0, 39),
            by = std::clamp(int((t.position.y - 40) / bucket), 0, 39);
        buckets[size_t(by * 40 + bx)].push_back(t.position);
    }
    float worst = 0;
    for (float y = 41; y < 439; y += 2) {
        for (float x = -129; x < 269; x += 2) {
            float nearest = std::numeric_limits<float>::infinity();
            int bx = int((x + 130) / bucket), by = int((y - 40) / bucket);
            for (int j = std::max(0, by - 1); j <= std::min(39, by + 1); ++j) {
                for (int i = std::max(0, bx - 1); i <= std::min(39, bx + 1); ++i) {
                    for (Vec2f p : buckets[size_t(j * 40 + i)]) {
                        Vec2f d = p - Vec2f{x, y};
                        nearest = std::min(nearest, std::sqrt(dot(d, d)));
                    }
                }
            }
            worst = std::max(worst, nearest);
        }
    }
    EXPECT_LT(worst, 2 * spacing);
}

TEST(TreePlacement, TreesAreDrawnWithinTheStand) {
    std::vector<PlacedTree> trees = plantedArea(square(0, 0, 500), forest(), 5, 77);
    size_t conifers = 0;
    size_t perVariant[kTreeVariants] = {};
    for (const PlacedTree &t : trees) {
        ASSERT_NE(t.kind, TreeKind::Mixed);
        conifers += t.kind == TreeKind::Conifer;
        ASSERT_LT(t.variant, kTreeVariants);
        ++perVariant[t.variant];
        EXPECT_GE(t.height, 12.0f);
        EXPECT_LE(t.height, 28.0f);
        EXPECT_GE(t.rotation, 0.0f);
        EXPECT_LT(t.rotation, 2 * kPi);
        EXPECT_GE(t.widthScale, 0.88f);
        EXPECT_LE(t.widthScale, 1.12f);
    }
    double share = double(conifers) / double(trees.size());
    EXPECT_NEAR(share, 0.4, 0.02);
    for (size_t n : perVariant) EXPECT_NEAR(double(n) / double(trees.size()), 1.0 / kTreeVariants, 0.02);
    for (const PlacedTree &t : plantedArea(square(0, 0, 100), forest(TreeKind::Conifer), 5, 77)) {
        EXPECT_EQ(t.kind, TreeKind::Conifer);
    }
}

TEST(TreePlacement, LimitStopsPlanting) {
    TreeSet set;
    set.limit = 250;
    plantArea(set, square(0, 0, 1000), forest(), 1, 1);
    EXPECT_EQ(set.trees.size(), 250u);
    EXPECT_TRUE(set.limitReached);
    plantPoints(set, {{1, 1}}, treeStand(LandClass::TreeRow, TreeKind::Mixed), 1, 2);
    EXPECT_EQ(set.trees.size(), 250u);

    TreeSet roomy;
    plantArea(roomy, square(0, 0, 50), forest(), 1, 1);
    EXPECT_FALSE(roomy.limitReached);
}

TEST(TreePlacement, DegenerateInputPlantsNothing) {
    TreeSet set;
    plantArea(set, {{0, 0}, {10, 0}}, forest(), 1, 1);
    plantArea(set, {{0, 0}, {10, 0}, {std::nanf(""), 5}}, forest(), 1, 1);
    plantArea(set, {{0, 0}, {10, 0}, {20, 0}}, forest(), 1, 1);  // no area
    plantPoints(set, {{std::nanf(""), 0}}, forest(), 1, 1);
    EXPECT_TRUE(set.trees.empty());
    TreeStand none = forest();
    none.spacing = 0;
    EXPECT_THROW(plantArea(set, square(0, 0, 10), none, 1, 1), std::invalid_argument);
    none.spacing = std::nanf("");
    EXPECT_THROW(plantLine(set, {{0, 0}, {10, 0}}, none, 1, 1), std::invalid_argument);
    EXPECT_THROW(plantArea(set, {{0, 0}, {1e30f, 0}, {0, 10}}, forest(), 1, 1), std::invalid_argument);
    EXPECT_THROW(plantLine(set, {{0, 0}, {0, -2e6f}}, forest(), 1, 1), std::invalid_argument);
    EXPECT_TRUE(set.trees.empty());
}

float distanceToSegment(Vec2f p, Vec2f a, Vec2f b) {
    Vec2f ab = b - a;
    float t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0f, 1.0f);
    Vec2f d = p - (a + ab * t);
    return std::sqrt(dot(d, d));
}

TEST(TreePlacement, RowsFollowTheLineAtTheirSpacing) {
    // An L of 60 m + 48 m: 12 trees at 9 m.
    const std::vector<Vec2f> line = {{0, 0}, {60, 0}, {60, 48}};
    TreeStand stand = treeStand(LandClass::TreeRow, TreeKind::Broadleaf);
    TreeSet set;
    plantLine(set, line, stand, 4, 12);
    ASSERT_EQ(set.trees.size(), 12u);
    for (const PlacedTree &t : set.trees) {
        float d =
            std::min(distanceToSegment(t.position, line[0], line[1]), distanceToSegment(t.position, line[1], line[2]));
        EXPECT_LT(d, 1e-3f);
        EXPECT_EQ(t.kind, TreeKind::Broadleaf);
    }
    // Along the first leg, consecutive trees are a spacing apart within the jitter.
    for (size_t i = 1; i < set.trees.size() && set.trees[i].position.x < 59; ++i) {
        float gap = set.trees[i].position.x - set.trees[i - 1].position.x;
        EXPECT_GE(gap, 9 * (1 - 2 * stand.rowJitter) - 1e-3f);
        EXPECT_LE(gap, 9 * (1 + 2 * stand.rowJitter) + 1e-3f);
    }
    TreeSet again;
    plantLine(again, line, stand, 4, 12);
    EXPECT_TRUE(sameTrees(set.trees, again.trees));

    TreeSet shortRow;
    plantLine(shortRow, {{0, 0}, {3, 4}}, stand, 4, 13);
    ASSERT_EQ(shortRow.trees.size(), 1u);
    EXPECT_LT(distanceToSegment(shortRow.trees[0].position, {0, 0}, {3, 4}), 1e-4f);
}

TEST(TreePlacement, PointsGetOneTreeEach) {
    TreeSet set;
    plantPoints(set, {{5, 6}, {-3, 2}}, treeStand(LandClass::TreeRow, TreeKind::Conifer), 1, 3);
    ASSERT_EQ(set.trees.size(), 2u);
    EXPECT_FLOAT_EQ(set.trees[1].position.x, -3.0f);
    EXPECT_EQ(set.trees[0].kind, TreeKind::Conifer);
}

TEST(TreePlacement, TransformScalesTurnsAndStandsTheTree) {
    PlacedTree tree{.position = {10, -4},
                    .kind = TreeKind::Conifer,
                    .variant = 0,
                    .height = 20,
                    .rotation = kPi / 2,
                    .widthScale = 0.9f};
    Transform m = treeTransform(tree, 150);
    Vec3f top = m.applyPoint({0, 0, 1});
    EXPECT_NEAR(top.x, 10, 1e-4f);
    EXPECT_NEAR(top.y, -4, 1e-4f);
    EXPECT_NEAR(top.z, 170, 1e-3f);
    Vec3f side = m.applyVector({1, 0, 0});  // turned a quarter to +y
    EXPECT_NEAR(side.x, 0, 1e-4f);
    EXPECT_NEAR(side.y, 18, 1e-4f);
}

}  // namespace
}  // namespace veduta
