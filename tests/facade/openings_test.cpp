#include "facade/openings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace veduta {
namespace {

void expectNear(Vec2d actual, Vec2d expected, double tolerance = 1e-12) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

const CoarseOpening kUnit{{0, 0}, {1, 0}, {1, 2}, {0, 2}};  // §8 row 8's opening (0,0)–(1,2)

TEST(Openings, CoarseOpeningIsPlacedRelativeToTheWall) {
    CoarseOpening o = coarseOpening(WallQuad::rectangle({0, 0}, {10, 3}), 0.4, 0.6, 0.3, 0.8);
    expectNear(o.bl, {4, 0.9});
    expectNear(o.tr, {6, 2.4});
    expectNear(o.br, {6, 0.9});
    expectNear(o.tl, {4, 2.4});
    EXPECT_THROW(coarseOpening(WallQuad::rectangle({0, 0}, {10, 3}), 0.6, 0.4, 0.3, 0.8), std::invalid_argument);
}

TEST(Openings, AbsolutePlacementSharesTheFreeWidthByTheDistances) {
    WallQuad wall = WallQuad::rectangle({0, 0}, {10, 3});
    CoarseOpening centred = placeOpening(wall, {2, 1.5, 1, 1, 0.9});
    expectNear(centred.bl, {4, 0.9});
    expectNear(centred.tr, {6, 2.4});
    CoarseOpening left = placeOpening(wall, {2, 1.5, 1, 7, 0.9});
    expectNear(left.bl, {1, 0.9});
    EXPECT_THROW(placeOpening(wall, {2, 2.5, 1, 1, 0.9}), std::invalid_argument);
}

TEST(Openings, NonDominantRightEdgeEndsUnderTheTopBand) {
    std::array<EdgeRefinement, 4> e;
    e[kRight].distB = 0.1;
    e[kTop].size = 0.3;
    RefinedOpening o = refineOpening(kUnit, e);
    expectNear(o.edges[kRight].r, {0.9, 1.4});
    expectNear(o.edges[kRight].l, {0.9, 0});
    expectNear(o.edges[kTop].l, {1, 1.4});
    expectNear(o.edges[kTop].r, {0, 1.4});
    EXPECT_TRUE(o.edges[kTop].dominant);
    EXPECT_FALSE(o.edges[kRight].dominant);
}

TEST(Openings, LeftEdgeMovesIntoTheOpening) {
    std::array<EdgeRefinement, 4> e;
    e[kLeft].distB = 0.1;
    RefinedOpening o = refineOpening(kUnit, e);
    expectNear(o.edges[kLeft].l, {0.1, 2});
    expectNear(o.edges[kLeft].r, {0.1, 0});
}

TEST(Openings, DistancesTrimFromTheEdgesStartAndEnd) {
    std::array<EdgeRefinement, 4> e;
    e[kBottom] = {0.1, 0.2, 0.25, 0, {}};
    e[kTop].distL = 0.3;
    RefinedOpening o = refineOpening(kUnit, e);
    expectNear(o.edges[kBottom].l, {0.1, 0.5});
    expectNear(o.edges[kBottom].r, {0.8, 0.5});
    expectNear(o.edges[kTop].l, {0.7, 2});
    // The right edge starts on the bottom's refined line.
    expectNear(o.edges[kRight].l, {1, 0.5});
}

TEST(Openings, ProfileIsScaledIntoTheSizeBand) {
    std::array<EdgeRefinement, 4> e;
    e[kTop] = {0, 0, 0, 0.3, {{0, 0}, {0.5, 1}, {1, 0}}};
    RefinedOpening o = refineOpening(kUnit, e);
    std::vector<Vec2d> outline = o.outline();
    std::vector<Vec2d> expected{{0, 0}, {1, 0}, {1, 1.4}, {0.5, 2}, {0, 1.4}};
    ASSERT_EQ(outline.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) expectNear(outline[i], expected[i]);
}

TEST(Openings, LeftAndRightDominanceLetsTheSidesRunFullHeight) {
    std::array<EdgeRefinement, 4> e;
    e[kBottom].distB = 0.1;
    e[kLeft].distB = 0.2;
    RefinedOpening o = refineOpening(kUnit, e, Dominance::LeftAndRight);
    expectNear(o.edges[kLeft].r, {0.2, 0});
    expectNear(o.edges[kBottom].l, {0.2, 0.2});
    EXPECT_THROW(
        [&] {
            e[kTop].size = 0.2;
            refineOpening(kUnit, e, Dominance::LeftAndRight);
        }(),
        std::invalid_argument);
}

TEST(Openings, DoorsIgnoreTheBottomRefinement) {
    std::array<EdgeRefinement, 4> e;
    e[kBottom].distB = 0.2;
    RefinedOpening o = refineOpening(kUnit, e, Dominance::BottomAndTop, OpeningKind::Door);
    expectNear(o.edges[kBottom].l, {0, 0});
}

TEST(Openings, BadRefinementsAreRefused) {
    std::array<EdgeRefinement, 4> e;
    e[kTop].size = 1.5;
    EXPECT_THROW(refineOpening(kUnit, e), std::invalid_argument);
    e[kTop] = {0.6, 0.5, 0, 0, {}};
    EXPECT_THROW(refineOpening(kUnit, e), std::invalid_argument);
    e[kTop] = {0, 0, 0.5, 0, {}};
    e[kBottom].size = 0.5;
    EXPECT_THROW(refineOpening(kUnit, e), std::invalid_argument);
    e = {};
    e[kRight].size = 0.2;
    EXPECT_THROW(refineOpening(kUnit, e), std::invalid_argument);
    e = {};
    e[kTop] = {0, 0, 0, 0.3, {{0.5, 1.2}}};
    EXPECT_THROW(refineOpening(kUnit, e), std::invalid_argument);
}

TEST(Openings, LeftEdgeMovesAlongTheTopEdgeOnANonParallelogram) {
    // A wall with a sloping top: the opening's top edge is steeper than its bottom edge.
    WallQuad wall{{0, 0}, {4, 0}, {4, 3}, {0, 2}};
    CoarseOpening c = coarseOpening(wall, 0.25, 0.75, 0.2, 0.8);
    expectNear(c.bl, {1, 0.45});
    expectNear(c.br, {3, 0.55});
    expectNear(c.tr, {3, 2.2});
    expectNear(c.tl, {1, 1.8});
    std::array<EdgeRefinement, 4> e;
    e[kLeft].distB = 0.1;
    RefinedOpening o = refineOpening(c, e);
    // in = f_tr − f_tl = (2, 0.4), not f_br − f_bl = (2, 0.1).
    expectNear(o.inward[kLeft], {2, 0.4});
    expectNear(o.edges[kLeft].l, {1.2, 1.84});
    expectNear(o.edges[kLeft].r, {1.2, 0.49});
}

TEST(Openings, NonFiniteOrDegenerateQuadsAreRefused) {
    const double nan = std::nan(""), inf = HUGE_VAL;
    EXPECT_THROW(coarseOpening({{0, 0}, {nan, 0}, {4, 3}, {0, 3}}, 0.2, 0.4, 0.2, 0.8), std::invalid_argument);
    WallQuad wall = WallQuad::rectangle({0, 0}, {10, 3});
    EXPECT_THROW(placeOpening(wall, {inf, 1.5, 1, 1, 0.9}), std::invalid_argument);
    EXPECT_THROW(placeOpening(wall, {2, 1.5, inf, 1, 0.9}), std::invalid_argument);
    EXPECT_THROW(placeOpening(wall, {2, 1.5, 1, nan, 0.9}), std::invalid_argument);
    std::array<EdgeRefinement, 4> e;
    EXPECT_THROW(refineOpening({{0, 0}, {1, 0}, {1, nan}, {0, 1}}, e), std::invalid_argument);
    EXPECT_THROW(refineOpening({{0, 0}, {0, 0}, {0, 0}, {0, 0}}, e), std::invalid_argument);  // no area
    EXPECT_THROW(refineOpening({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, e), std::invalid_argument);  // clockwise
    EXPECT_THROW(refineOpening({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, e), std::invalid_argument);  // crossed
    EXPECT_THROW(refineOpening({{0, 0}, {1e300, 0}, {1e300, 1e300}, {0, 1e300}}, e), std::invalid_argument);
    EXPECT_NO_THROW(refineOpening(kUnit, e));
}

}  // namespace
}  // namespace veduta
