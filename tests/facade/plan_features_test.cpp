#include "facade/plan_features.h"

#include <gtest/gtest.h>

namespace veduta {
namespace {

// Fig. 4.4 mirrored into counter-clockwise order (see floor_plan.h): the pentagon fpm1 = p1..p5
// and the square fpm2 = q1..q4 docked with k2 on e5[a, b].
FloorPlanModule pentagon() { return {{{0, 0}, {1, 3}, {-2, 5}, {-5, 3}, {-4, 0}}, "", 0.4, 3, "", {}}; }
FloorPlanModule square() { return {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "", 0.4, 3, "", {}}; }
FloorPlanModule rectangle(double x0, double y0, double x1, double y1) {
    return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, "", 0.3, 3, "", {}};
}

constexpr double kA = 0.25, kB = 0.75;

// Edge `edge` of `module` from t0 to t1.
void expectPiece(const WalkPiece &piece, int module, int edge, double t0, double t1) {
    EXPECT_EQ(piece.element, (PlanElement{false, module, edge}));
    EXPECT_EQ(piece.t0, t0);
    EXPECT_EQ(piece.t1, t1);
}

TEST(PlanFeatures, SingleModuleIsOneFeatureOfItsWholeOutline) {
    FloorPlan plan({pentagon()}, {}, {});
    std::vector<Feature> features = planFeatures(plan);
    ASSERT_EQ(features.size(), 1u);
    ASSERT_EQ(features[0].edges.size(), 5u);
    for (int i = 0; i < 5; ++i) expectPiece(features[0].edges[i], 0, i, 0, 1);
}

TEST(PlanFeatures, DockedModuleSplitsTheOutlineIntoTwoFeatures) {
    // §8 row 2, Fig. 4.4: fpm1 = e5[b,1], e1, e2, e3, e4, e5[0,a]; fpm2 = k3, k4, k1.
    FloorPlan plan({pentagon(), square()}, {{false, 0, 4, 1, 1, kA, kB, {}}}, {});
    std::vector<Feature> features = planFeatures(plan);
    ASSERT_EQ(features.size(), 2u);
    const Feature &f2 = features[0].module == 1 ? features[0] : features[1];
    const Feature &f1 = features[0].module == 0 ? features[0] : features[1];
    ASSERT_EQ(f1.module, 0);
    ASSERT_EQ(f2.module, 1);
    ASSERT_EQ(f1.edges.size(), 6u);
    expectPiece(f1.edges[0], 0, 4, kB, 1);
    for (int i = 0; i < 4; ++i) expectPiece(f1.edges[1 + i], 0, i, 0, 1);
    expectPiece(f1.edges[5], 0, 4, 0, kA);
    ASSERT_EQ(f2.edges.size(), 3u);
    expectPiece(f2.edges[0], 1, 2, 0, 1);
    expectPiece(f2.edges[1], 1, 3, 0, 1);
    expectPiece(f2.edges[2], 1, 0, 0, 1);
    // The features chain: each ends where the next begins.
    EXPECT_EQ(f1.edges.back().to, f2.edges.front().from);
    EXPECT_EQ(f2.edges.back().to, f1.edges.front().from);
}

TEST(PlanFeatures, EdgeBetweenTwoDocksIsAFeatureOfItsOwn) {
    // Case 6 (Fig. 4.11): c1[b1, a2] between two modules docked on one edge.
    FloorPlan plan({pentagon(), square(), square()},
                   {{false, 0, 4, 1, 1, 0.1, 0.3, {}}, {false, 0, 4, 2, 1, 0.6, 0.9, {}}}, {});
    std::vector<Feature> features = planFeatures(plan);
    ASSERT_EQ(features.size(), 4u);
    int between = 0;
    for (const Feature &f : features) {
        if (f.module != 0 || f.edges.size() != 1) continue;
        expectPiece(f.edges[0], 0, 4, 0.3, 0.6);
        ++between;
    }
    EXPECT_EQ(between, 1);
}

TEST(PlanFeatures, ChainOfDocksTracesTheOutlineOfTheUnion) {
    // fpm0 <- fpm1 <- fpm2 in a row. fpm1 has two features: below, from its end at fpm0 (fpm0
    // dominant) to c[0, a] at fpm2 (case 3); above, from fpm2's end to fpm0 (case 5).
    FloorPlan plan({rectangle(0, 0, 4, 4), square(), square()},
                   {{false, 0, 1, 1, 3, 0, 0.5, {}}, {false, 1, 1, 2, 3, 0.5, 1, {}}}, {});
    std::vector<Feature> features = planFeatures(plan);
    ASSERT_EQ(features.size(), 4u);
    int middle = 0;
    for (const Feature &f : features) middle += f.module == 1;
    EXPECT_EQ(middle, 2);
    std::vector<Vec2d> outline = featureOutline(features);
    // The union's outline, counter-clockwise, with the dock points as collinear vertices.
    std::vector<Vec2d> expected = {{0, 0}, {4, 0}, {6, 0}, {6, 1}, {7, 1}, {7, 2}, {6, 2}, {4, 2}, {4, 4}, {0, 4}};
    ASSERT_EQ(outline.size(), expected.size());
    size_t start = 0;
    while (start < outline.size() && !(outline[start] == expected[0])) ++start;
    ASSERT_LT(start, outline.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(outline[(start + i) % outline.size()].x, expected[i].x, 1e-12);
        EXPECT_NEAR(outline[(start + i) % outline.size()].y, expected[i].y, 1e-12);
    }
}

TEST(PlanFeatures, BarePpEdgeIsAFeatureAndTheInnerOneIsInNone) {
    // Fig. 4.15 / case 8: two towers joined by three PP edges; the middle one is inside.
    FloorPlan plan({rectangle(0, 0, 2, 4), rectangle(4, 0, 6, 4)}, {},
                   {{0, 1, 0.125, 1, 3, 0.875, {}}, {0, 1, 0.5, 1, 3, 0.5, {}}, {0, 1, 0.875, 1, 3, 0.125, {}}});
    std::vector<Feature> features = planFeatures(plan);
    ASSERT_EQ(features.size(), 4u);
    int bare = 0;
    for (const Feature &f : features) {
        if (f.module >= 0) continue;
        ASSERT_EQ(f.edges.size(), 1u);
        EXPECT_EQ(f.edges[0].element.index, f.ppConnection);
        EXPECT_NE(f.ppConnection, 1);
        ++bare;
    }
    EXPECT_EQ(bare, 2);
}

TEST(PlanFeatures, PpEdgeEndsJoinTheModuleDockedOnIt) {
    // Case 7 (Fig. 4.12): g = (r_a, r_b) from fpm2's top left corner to fpm1's top left corner
    // carries fpm3 on g[0.25, 0.75]; fpm3's feature is g[0, a2], its own edges, g[b2, 1].
    FloorPlan plan({rectangle(0, 0, 4, 4), rectangle(0, 0, 2, 2), square()},
                   {{false, 0, 2, 1, 0, 0, 0.5, {}}, {true, 0, 0, 2, 0, 0.25, 0.75, {}}}, {{1, 3, 0, 0, 2, 1, {}}});
    std::vector<Feature> features = planFeatures(plan);
    const Feature *docked = nullptr;
    for (const Feature &f : features)
        if (f.module == 2) docked = &f;
    ASSERT_NE(docked, nullptr);
    ASSERT_EQ(docked->edges.size(), 5u);
    EXPECT_EQ(docked->edges[0].element, (PlanElement{true, 0, 0}));
    EXPECT_EQ(docked->edges[0].t0, 0);
    EXPECT_EQ(docked->edges[0].t1, 0.25);
    expectPiece(docked->edges[1], 2, 1, 0, 1);
    expectPiece(docked->edges[2], 2, 2, 0, 1);
    expectPiece(docked->edges[3], 2, 3, 0, 1);
    EXPECT_EQ(docked->edges[4].element, (PlanElement{true, 0, 0}));
    EXPECT_EQ(docked->edges[4].t0, 0.75);
    EXPECT_EQ(docked->edges[4].t1, 1);
    // No feature of the PP edge alone is left.
    for (const Feature &f : features) EXPECT_GE(f.module, 0);
}

}  // namespace
}  // namespace veduta
