#include "facade/wall_mask.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <gtest/gtest.h>

#include "core/hash.h"
#include "core/polygon_area.h"

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double lowX, double lowY, double highX, double highY) {
    return {{lowX, lowY}, {highX, lowY}, {highX, highY}, {lowX, highY}};
}

// A 4 m × 3 m wall with a 1 m window at (1, 1); grown by 0.1 m of mortar it blocks [0.9, 2.1]².
WallFace wallWithWindow() { return {rectangle(0, 0, 4, 3), {rectangle(1, 1, 2, 2)}}; }

TEST(WallMask, GreyImageIsBlackFreeWhiteBlockedAndGreyWhereTheGrownOpeningCrosses) {
    WallMask mask(wallWithWindow(), 0.1, 0.25);
    ASSERT_EQ(mask.columns(), 16);
    ASSERT_EQ(mask.rows(), 12);
    EXPECT_EQ(mask.grey(0, 0), 0.0f);  // the wall's own edges lie on cells' sides and cross none
    EXPECT_EQ(mask.grey(15, 11), 0.0f);
    EXPECT_EQ(mask.grey(5, 5), 1.0f);  // [1.25, 1.5]²: inside the window
    EXPECT_EQ(mask.grey(3, 5), 0.5f);  // [0.75, 1.0] × [1.25, 1.5]: the grown jamb at x = 0.9
    EXPECT_EQ(mask.grey(4, 5), 1.0f);  // [1.0, 1.25]: the mortar joint around the window is blocked too
    EXPECT_EQ(mask.grey(8, 5), 0.5f);  // [2.0, 2.25]: the right jamb at 2.1
    EXPECT_EQ(mask.grey(9, 5), 0.0f);
    EXPECT_EQ(mask.grey(5, 3), 0.5f);  // [0.75, 1.0] in y: the sill's joint at 0.9
}

TEST(WallMask, TheImageBracketsTheExactFreeArea) {
    WallFace wall{{{0, 0}, {6, 0}, {6, 3}, {3, 4.5}, {0, 3}}, {rectangle(1, 1, 2, 2.5), {{4, 1}, {5, 1}, {4.5, 2}}}};
    WallMask mask(wall, 0.05, 0.1);
    double black = 0, notWhite = 0, cell = mask.cellSize() * mask.cellSize();
    for (int row = 0; row < mask.rows(); ++row) {
        for (int column = 0; column < mask.columns(); ++column) {
            black += mask.grey(column, row) == 0.0f ? cell : 0;
            notWhite += mask.grey(column, row) < 1.0f ? cell : 0;
        }
    }
    // Gable wall 6 × 3 + 4.5 of gable; window 1.1 × 1.6 grown; the triangle (area 0.5, 1 × 1 wide
    // and high) grown by a square of half-side r: 0.5 + 2r(1 + 1) + 4r².
    EXPECT_GT(mask.freeArea(), 20);
    EXPECT_LE(black, mask.freeArea());
    EXPECT_GE(notWhite, mask.freeArea());
    EXPECT_NEAR(mask.freeArea(), 18 + 4.5 - 1.1 * 1.6 - (0.5 + 0.2 + 0.01), 1e-12);
}

TEST(WallMask, CoverReadsTheMeanGreyUnderARectangle) {
    WallMask mask(wallWithWindow(), 0.1, 0.25);
    EXPECT_EQ(mask.cover({0.1, 0.1}, {0.6, 0.4}), MaskCover::Free);
    EXPECT_EQ(mask.cover({1.2, 1.2}, {1.8, 1.7}), MaskCover::Blocked);
    EXPECT_EQ(mask.cover({0.5, 1.2}, {1.5, 1.4}), MaskCover::Mixed);
    EXPECT_EQ(mask.cover({5, 1}, {6, 2}), MaskCover::Blocked);    // beyond the wall
    EXPECT_EQ(mask.cover({3.5, 1}, {4.5, 2}), MaskCover::Mixed);  // half beyond it
}

TEST(WallMask, FreeSpansEndAtTheGrownOpenings) {
    WallMask mask(wallWithWindow(), 0.1, 0.25);
    auto spans = mask.freeSpans(1.2, 1.5);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_DOUBLE_EQ(spans[0].low, 0);
    EXPECT_NEAR(spans[0].high, 0.9, 1e-12);
    EXPECT_NEAR(spans[1].low, 2.1, 1e-12);
    EXPECT_DOUBLE_EQ(spans[1].high, 4);
    EXPECT_LE(spans[0].high, 0.9);  // never into the blocked part
    EXPECT_GE(spans[1].low, 2.1);
    EXPECT_EQ(mask.freeSpans(0.5, 1.0).size(), 2u);
    // Touching the joint's edge is not entering it (a mortar of 1/8 m puts it exactly at 0.875).
    WallMask eighth(wallWithWindow(), 0.125, 0.25);
    EXPECT_EQ(eighth.freeSpans(0.2, 0.875).size(), 1u);
    EXPECT_EQ(eighth.freeSpans(0.2, 0.876).size(), 2u);
}

TEST(WallMask, OpeningsWhoseJointsMeetBlockOneSpan) {
    WallFace wall{rectangle(0, 0, 4, 3), {rectangle(1, 1, 1.5, 2), rectangle(1.6, 1, 2, 2)}};
    auto spans = WallMask(wall, 0.1, 0.25).freeSpans(1.2, 1.5);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_NEAR(spans[0].high, 0.9, 1e-12);
    EXPECT_NEAR(spans[1].low, 2.1, 1e-12);
}

TEST(WallMask, ClipCutsExactlyAndOpensHolesIntoTheOutline) {
    WallMask mask(wallWithWindow(), 0.1, 0.25);
    auto pieces = mask.clip(rectangle(0.5, 0.5, 1.5, 1.5));
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_NEAR(signedArea(pieces[0]), 1 - 0.6 * 0.6, 1e-12);

    // A stone larger than the grown window around it would keep a hole: it comes back in parts
    // without holes, counter-clockwise, together the stone minus the grown window.
    auto parts = mask.clip(rectangle(0.5, 0.5, 2.5, 2.5));
    ASSERT_GE(parts.size(), 2u);
    double total = 0;
    for (const auto &part : parts) {
        EXPECT_GT(signedArea(part), 0);
        total += signedArea(part);
    }
    EXPECT_NEAR(total, 4 - 1.2 * 1.2, 1e-12);
    EXPECT_NEAR(mask.freeArea(), 12 - 1.2 * 1.2, 1e-12);
    EXPECT_TRUE(mask.clip(rectangle(1.2, 1.2, 1.8, 1.8)).empty());
}

TEST(WallMask, RectanglesCutAlongTheAxesAgreeWithTheExactRegion) {
    // Openings whose grown joints meet (the two left ones) and one at the wall's foot, on a gable
    // wall: stones straddle axis-parallel joints, the slanted roof line, both and several at once,
    // and the pieces must make up exactly the stone within the free region. (The triangle, which
    // the stones keep clear of, makes the region's rings not all axis-parallel.)
    using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
    using Polygon = CGAL::Polygon_2<Kernel>;
    WallFace wall{
        {{0, 0}, {8, 0}, {8, 3}, {4, 5}, {0, 3}},
        {rectangle(1, 1, 2, 2.5), rectangle(2.15, 1, 3, 2.5), rectangle(4, 0, 5, 2.2), {{6, 1}, {7, 1}, {6.5, 2}}}};
    double mortar = 0.1;
    WallMask mask(wall, mortar, 0.2);
    auto exact = [](const std::vector<Vec2d> &ring) {
        Polygon polygon;
        for (Vec2d p : ring) polygon.push_back({p.x, p.y});
        return polygon;
    };
    CGAL::Polygon_set_2<Kernel> region(exact(wall.outline));
    for (const auto &opening : wall.openings) {
        CGAL::Polygon_set_2<Kernel> openingSet(exact(opening));
        for (double dx : {-mortar, mortar})
            for (double dy : {-mortar, mortar}) {
                std::vector<Vec2d> moved;
                for (Vec2d p : opening) moved.push_back({p.x + dx, p.y + dy});
                openingSet.join(exact(moved));
            }
        // A rectangle grown by a square is the union of its four shifted copies.
        if (opening.size() == 4) region.difference(openingSet);
    }
    size_t cut = 0;
    for (uint32_t i = 0; i < 400; ++i) {
        // Left of the triangle's joint (x < 5.9), and up into the gable's slope.
        double u = bitsToUnitFloat(hashValues({i, 1})), y = -0.2 + 3.4 * bitsToUnitFloat(hashValues({i, 2}));
        double x = i % 2 ? 3.9 + 0.9 * u : 0.6 + 2.6 * u;
        double w = 0.05 + 0.5 * bitsToUnitFloat(hashValues({i, 3})),
               h = 0.05 + 0.3 * bitsToUnitFloat(hashValues({i, 4}));
        std::vector<Vec2d> stone = rectangle(x, y, x + w, y + h);
        auto pieces = mask.clip(stone);
        double total = 0;
        for (const auto &piece : pieces) {
            EXPECT_GT(signedArea(piece), 0);
            total += signedArea(piece);
        }
        CGAL::Polygon_set_2<Kernel> inside(region);
        inside.intersection(exact(stone));
        std::vector<CGAL::Polygon_with_holes_2<Kernel>> parts;
        inside.polygons_with_holes(std::back_inserter(parts));
        double expected = 0;
        for (const auto &part : parts) {
            expected += CGAL::to_double(part.outer_boundary().area());
            for (const auto &hole : part.holes()) expected += CGAL::to_double(hole.area());
        }
        EXPECT_NEAR(total, expected, 1e-12) << "stone " << i;
        cut += !pieces.empty() && std::abs(total - w * h) > 1e-9;
    }
    EXPECT_GT(cut, 50u);
}

// Openings are mostly rectangles, often with points between their corners (refined edges); grown,
// such an opening is the rectangle widened by the mortar, exactly as the Minkowski sum that a
// slanted opening takes makes it.
TEST(WallMask, ARectangleWithPointsAlongItsSidesGrowsAsTheRectangleDoes) {
    std::vector<Vec2d> refined{{1, 1}, {1.25, 1}, {1.5, 1}, {2, 1}, {2, 1.5}, {2, 2}, {1.5, 2}, {1, 2}, {1, 1.2}};
    WallMask plain(wallWithWindow(), 0.1, 0.25);
    WallMask withPoints({rectangle(0, 0, 4, 3), {refined}}, 0.1, 0.25);
    EXPECT_DOUBLE_EQ(withPoints.freeArea(), 12 - 1.2 * 1.2);
    EXPECT_DOUBLE_EQ(withPoints.freeArea(), plain.freeArea());
    for (int row = 0; row < plain.rows(); ++row)
        for (int column = 0; column < plain.columns(); ++column)
            EXPECT_EQ(withPoints.grey(column, row), plain.grey(column, row)) << column << " " << row;
    // The same opening as a slanted quadrilateral's limit: a rhombus grows by the square's
    // Minkowski sum, its area that of the rhombus plus its swept sides and the square.
    std::vector<Vec2d> rhombus{{2, 1}, {3, 1.5}, {2, 2}, {1, 1.5}};
    WallMask slanted({rectangle(0, 0, 4, 3), {rhombus}}, 0.1, 0.25);
    // Rhombus 1 (diagonals 2 and 1); each side (length √1.25) swept by the square's width across it
    // (0.2 · (|dx| + |dy|) / length per unit length), plus the square 0.04.
    double sides = 4 * 0.1 * (1 + 0.5) * 2 / 2;
    EXPECT_NEAR(slanted.freeArea(), 12 - (1 + sides + 0.04), 1e-9);
}

TEST(WallMask, ACellSizeTooFineForTheWallIsCoarsened) {
    WallMask mask({rectangle(0, 0, 1000, 1000), {}}, 0, 0.001);
    EXPECT_LE(size_t(mask.columns()) * size_t(mask.rows()), kMaskCellLimit);
    EXPECT_GE(mask.columns() * mask.cellSize(), 1000);
    EXPECT_EQ(mask.cover({1, 1}, {999, 999}), MaskCover::Free);
}

}  // namespace
}  // namespace veduta
