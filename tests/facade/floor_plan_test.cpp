#include "facade/floor_plan.h"

#include <gtest/gtest.h>

#include <string>

namespace veduta {
namespace {

// The pentagon fpm1 of Figs 4.1/4.4, mirrored (x -> -x) into counter-clockwise order, so that
// p1..p5 and e1..e5 keep the thesis's names (floor_plan.h).
FloorPlanModule pentagon() { return {{{0, 0}, {1, 3}, {-2, 5}, {-5, 3}, {-4, 0}}, "Risalit", 0.4, 3, "brick", {}}; }

// A square in its own coordinates, turned by 45 degrees and off the origin, so that docking
// must rotate, scale and move it.
FloorPlanModule diamond() { return {{{10, 10}, {11, 11}, {10, 12}, {9, 11}}, "Erker", 0.3, 3, "brick", {}}; }

FloorPlanModule rectangle(double x0, double y0, double x1, double y1) {
    return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, "", 0.3, 3, "", {}};
}

constexpr int kE5 = 4;  // e5 = (p5, p1)
constexpr int kK2 = 1;  // k2 = (q2, q3)

void expectNear(Vec2d actual, Vec2d expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

std::string errorOf(const std::vector<FloorPlanModule> &modules, const std::vector<KkConnection> &kk,
                    const std::vector<PpConnection> &pp) {
    try {
        FloorPlan plan(modules, kk, pp);
    } catch (const InputError &e) {
        return e.what();
    }
    return "";
}

TEST(FloorPlan, DockedEdgeEndsLieOnTheDominantEdgeInterval) {
    FloorPlan plan({pentagon(), diamond()}, {{false, 0, kE5, 1, kK2, 0.25, 0.75, {}}}, {});
    const std::vector<Vec2d> &q = plan.modules()[1].outline;
    // Reversed orientation: q2 on c[b], q3 on c[a].
    expectNear(q[1], plan.edgePoint(0, kE5, 0.75), 1e-9);
    expectNear(q[2], plan.edgePoint(0, kE5, 0.25), 1e-9);
    expectNear(q[1], {-1, 0}, 1e-9);
    expectNear(q[2], {-3, 0}, 1e-9);
    // Scaled to the interval's length (2) and on the far side of e5 (y <= 0).
    expectNear(q[3], {-3, -2}, 1e-9);
    expectNear(q[0], {-1, -2}, 1e-9);
    EXPECT_EQ(plan.dockOf(1), 0);
    EXPECT_EQ(plan.dockOf(0), -1);
    EXPECT_EQ(plan.modules().size(), plan.kkConnections().size() + 1);
}

TEST(FloorPlan, ModuleAlreadyInPlaceKeepsItsExactCoordinates) {
    FloorPlanModule square = rectangle(-3, -2, -1, 0);  // its top edge (index 2) is e5[0.25, 0.75]
    FloorPlan plan({pentagon(), square}, {{false, 0, kE5, 1, 2, 0.25, 0.75, {}}}, {});
    EXPECT_EQ(plan.modules()[1].outline, square.outline);
}

TEST(FloorPlan, OverlappingIntervalsOnOneEdgeAreRejected) {
    std::string error =
        errorOf({pentagon(), diamond(), diamond()},
                {{false, 0, kE5, 1, kK2, 0.1, 0.5, {}}, {false, 0, kE5, 2, kK2, 0.4, 0.8, {"plan.txt", 7, 3}}}, {});
    EXPECT_EQ(error,
              "plan.txt:7:3: KK connection 1: the interval [0.4, 0.8] overlaps [0.1, 0.5] of KK connection 0 "
              "on the same edge");
}

TEST(FloorPlan, TouchingIntervalsAreAccepted) {
    EXPECT_EQ(errorOf({pentagon(), diamond(), diamond()},
                      {{false, 0, kE5, 1, kK2, 0.1, 0.4, {}}, {false, 0, kE5, 2, kK2, 0.4, 0.8, {}}}, {}),
              "");
}

TEST(FloorPlan, ModulesNeedOneDockLessThanTheyAreMany) {
    // |M| = |C_ee| + 1 (Def 4.5): three modules and one dock leave module 2 apart ...
    EXPECT_NE(errorOf({pentagon(), diamond(), diamond()}, {{false, 0, kE5, 1, kK2, 0.1, 0.4, {}}}, {})
                  .find("floor-plan module 2 is not connected to module 0"),
              std::string::npos);
    // ... and a second dock of the same module is one too many.
    EXPECT_NE(
        errorOf({pentagon(), diamond()}, {{false, 0, kE5, 1, kK2, 0.1, 0.4, {}}, {false, 0, 0, 1, 0, 0, 1, {}}}, {})
            .find("KK connection 1: module 1 is docked a second time"),
        std::string::npos);
}

TEST(FloorPlan, DocksInACycleAreRejected) {
    EXPECT_NE(
        errorOf({pentagon(), diamond()}, {{false, 1, 0, 0, 0, 0, 1, {}}, {false, 0, kE5, 1, kK2, 0.1, 0.4, {}}}, {})
            .find("its docks form a cycle"),
        std::string::npos);
}

TEST(FloorPlan, BadModulesAreRejectedWithTheirPlace) {
    FloorPlanModule clockwise{{{0, 0}, {0, 1}, {1, 0}}, "", 0, 0, "", {"plan.txt", 2, 1}};
    EXPECT_EQ(errorOf({clockwise}, {}, {}),
              "plan.txt:2:1: floor-plan module 0: the outline runs clockwise; outlines run counter-clockwise");
    FloorPlanModule concave{{{0, 0}, {4, 0}, {1, 1}, {0, 4}}, "", 0, 0, "", {}};
    EXPECT_NE(errorOf({concave}, {}, {}).find("not convex"), std::string::npos);
    EXPECT_NE(errorOf({pentagon(), diamond()}, {{false, 0, kE5, 1, kK2, 0.5, 0.5, {}}}, {}).find("0 <= a < b <= 1"),
              std::string::npos);
}

// Two rectangles side by side, x in [0,2] and [4,6]; their facing edges are fpm1's e1 (upwards)
// and fpm2's e3 (downwards).
std::vector<FloorPlanModule> twoTowers() { return {rectangle(0, 0, 2, 4), rectangle(4, 0, 6, 4)}; }

TEST(FloorPlan, CrossingPpEdgesAreRejected) {
    std::string error = errorOf(twoTowers(), {}, {{0, 1, 0.25, 1, 3, 0.25, {}}, {0, 1, 0.75, 1, 3, 0.75, {}}});
    EXPECT_EQ(error, "<input>: PP connection 1: its edge crosses PP connection 0");
}

TEST(FloorPlan, PpEdgeThroughAModuleIsRejected) {
    // From fpm1's left edge to fpm2: straight through fpm1.
    std::string error = errorOf(twoTowers(), {}, {{0, 3, 0.5, 1, 3, 0.5, {}}});
    EXPECT_EQ(error, "<input>: PP connection 0: its edge crosses module 0");
}

TEST(FloorPlan, PpModuleIsTheTriangleBetweenADockAndAPpEdge) {
    // Fig. 4.3 left: fpm2 docked on the right half of fpm1's top edge, a PP edge from fpm1's top
    // left corner to fpm2's top left corner encloses the triangle (s1, s2, s3).
    FloorPlan plan({rectangle(0, 0, 4, 4), rectangle(0, 0, 2, 2)}, {{false, 0, 2, 1, 0, 0, 0.5, {}}},
                   {{0, 2, 1, 1, 3, 0, {}}});
    expectNear(plan.modules()[1].outline[2], {4, 6}, 1e-12);
    std::vector<PpModule> pp = plan.ppModules();
    ASSERT_EQ(pp.size(), 1u);
    ASSERT_EQ(pp[0].outline.size(), 3u);
    // Counter-clockwise from the PP edge; the other two edges record the neighbouring modules.
    EXPECT_EQ(pp[0].outline[0], (Vec2d{2, 6}));
    EXPECT_EQ(pp[0].outline[1], (Vec2d{0, 4}));
    EXPECT_EQ(pp[0].outline[2], (Vec2d{2, 4}));
    EXPECT_EQ(pp[0].edgeSources[0], (PlanElement{true, 0, 0}));
    EXPECT_EQ(pp[0].edgeSources[1], (PlanElement{false, 0, 2}));
    EXPECT_EQ(pp[0].edgeSources[2], (PlanElement{false, 1, 3}));
}

TEST(FloorPlan, InnerPpEdgeIsIgnored) {
    // Fig. 4.15: three PP edges between two modules; the middle one lies inside the plan.
    FloorPlan plan(twoTowers(), {},
                   {{0, 1, 0.125, 1, 3, 0.875, {}}, {0, 1, 0.5, 1, 3, 0.5, {}}, {0, 1, 0.875, 1, 3, 0.125, {}}});
    EXPECT_TRUE(plan.ppOnOutline(0));
    EXPECT_FALSE(plan.ppOnOutline(1));
    EXPECT_TRUE(plan.ppOnOutline(2));
    for (const WalkPiece &piece : plan.outline()) EXPECT_FALSE(piece.element == (PlanElement{true, 1, 0}));
    // One PP module between the outer two PP edges; the inner one does not split it.
    std::vector<PpModule> pp = plan.ppModules();
    ASSERT_EQ(pp.size(), 1u);
    ASSERT_EQ(pp[0].outline.size(), 4u);
    EXPECT_EQ(pp[0].outline[0], (Vec2d{2, 0.5}));
    EXPECT_EQ(pp[0].outline[1], (Vec2d{4, 0.5}));
    EXPECT_EQ(pp[0].outline[2], (Vec2d{4, 3.5}));
    EXPECT_EQ(pp[0].outline[3], (Vec2d{2, 3.5}));
}

TEST(FloorPlan, ConcaveRegionBetweenPpEdgesGivesNoPpModule) {
    // Fig. 4.16: the region between the two PP edges wraps round fpm2's left corners.
    FloorPlan plan({rectangle(0, 0, 2, 4), rectangle(4, 1, 6, 3)}, {},
                   {{0, 1, 0, 1, 0, 0.5, {}}, {0, 1, 1, 1, 2, 0.5, {}}});
    EXPECT_TRUE(plan.ppOnOutline(0));
    EXPECT_TRUE(plan.ppOnOutline(1));
    EXPECT_TRUE(plan.ppModules().empty());
}

TEST(FloorPlan, ModuleDockedOnTheInnerSideOfAPpEdgeIsRejected) {
    // The PP edge of the Fig. 4.3 plan runs from fpm1 to fpm2, so the outline walks it from
    // r_b to r_a and a module docked right of (r_a, r_b) would lie inside.
    std::string error =
        errorOf({rectangle(0, 0, 4, 4), rectangle(0, 0, 2, 2), diamond()},
                {{false, 0, 2, 1, 0, 0, 0.5, {}}, {true, 0, 0, 2, 0, 0.25, 0.75, {}}}, {{0, 2, 1, 1, 3, 0, {}}});
    EXPECT_NE(error.find("KK connection 1: module 2 docks on the inner side of PP connection 0"), std::string::npos);
}

}  // namespace
}  // namespace veduta
