#include "facade/cyclopean.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "facade/convex_pieces.h"

namespace veduta {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Polygon polygon(const std::vector<Vec2d> &ring) {
    Polygon result;
    for (Vec2d p : ring) result.push_back({p.x, p.y});
    return result;
}

double ringArea(const std::vector<Vec2d> &ring) { return area(RegionPiece{ring, {}}); }

double perimeter(const std::vector<Vec2d> &ring) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) sum += length(ring[(i + 1) % ring.size()] - ring[i]);
    return sum;
}

// A 10 m × 3 m wall with a door standing on its foot and a window (the golden scene's gate).
WallFace wallWithDoorAndWindow() {
    return {rectangle(0, 0, 10, 3), {rectangle(2, 0, 3, 2.2), rectangle(5, 1, 6.2, 2.2)}};
}

CyclopeanMasonry description() {
    CyclopeanMasonry d;
    d.spacing = 0.5;
    d.lloyd = 30;
    d.startColour = {0.3f, 0.28f, 0.25f};
    d.endColour = {0.5f, 0.45f, 0.4f};
    d.joint = 0.03;
    d.mortarColour = {0.6f, 0.6f, 0.6f};
    d.depth = 0.02;
    d.loc = {"wall.txt", 4, 2};
    return d;
}

std::string errorOf(const CyclopeanMasonry &d) {
    try {
        cyclopeanMasonry(wallWithDoorAndWindow(), d, 1, 2);
    } catch (const InputError &error) {
        return error.what();
    }
    return "no error";
}

TEST(CyclopeanStoneCount, GivesTheThesisCountsOfRow15) {
    // digest-001 §8 row 15: a = b = 10, r = 1 → n1 5, n2 4, n_v ⌊5.62⌋ = 5, n = 3·5 + 2·4 = 23 → 18.
    CyclopeanStoneCount square = cyclopeanStoneCount(10, 10, 1);
    EXPECT_EQ(square.firstCourse, 5);
    EXPECT_EQ(square.secondCourse, 4);
    EXPECT_EQ(square.courses, 5);
    EXPECT_EQ(square.packed, 23);
    EXPECT_EQ(square.stones, 18);
    // a = 8, b = 3, r = 0.5 → n1 8, n2 7, n_v ⌊3.31⌋ = 3, n = 2·8 + 1·7 = 23 → 18.
    CyclopeanStoneCount strip = cyclopeanStoneCount(8, 3, 0.5);
    EXPECT_EQ(strip.firstCourse, 8);
    EXPECT_EQ(strip.secondCourse, 7);
    EXPECT_EQ(strip.courses, 3);
    EXPECT_EQ(strip.packed, 23);
    EXPECT_EQ(strip.stones, 18);
}

TEST(CyclopeanStoneCount, CountsExactCoursesWholeAndSmallWallsAsNone) {
    // b − 2r = 2·√3·r exactly: three courses, not two after rounding.
    EXPECT_EQ(cyclopeanStoneCount(10, 2 + 2 * std::sqrt(3.0), 1).courses, 3);
    EXPECT_EQ(cyclopeanStoneCount(1, 1, 1).packed, 0);
}

TEST(CornerSeeds, LieAcrossTheBisectorOfEveryReflexCorner) {
    WallRegion region(wallWithDoorAndWindow());
    std::vector<CornerSeeds> corners = cornerSeeds(region, 0.5);
    // The door's two upper corners and the window's four.
    ASSERT_EQ(corners.size(), 6u);
    struct Expected {
        Vec2d corner;
        Vec2d bisector;  // into the wall
    };
    const double h = std::sqrt(0.5);
    const Expected expected[] = {{{2, 2.2}, {-h, h}}, {{3, 2.2}, {h, h}},   {{5, 1}, {-h, -h}},
                                 {{6.2, 1}, {h, -h}}, {{6.2, 2.2}, {h, h}}, {{5, 2.2}, {-h, h}}};
    for (const Expected &e : expected) {
        auto found = std::find_if(corners.begin(), corners.end(),
                                  [&](const CornerSeeds &c) { return length(c.corner - e.corner) < 1e-12; });
        ASSERT_NE(found, corners.end()) << e.corner.x << ", " << e.corner.y;
        EXPECT_DOUBLE_EQ(found->distance, 0.5);  // no corners within 2·PD, no edge within PD
        Vec2d across{-e.bisector.y, e.bisector.x};
        Vec2d plus = e.corner + across * (found->distance / 2), minus = e.corner - across * (found->distance / 2);
        bool asListed = length(found->first - plus) < 1e-9 && length(found->second - minus) < 1e-9;
        bool swapped = length(found->first - minus) < 1e-9 && length(found->second - plus) < 1e-9;
        EXPECT_TRUE(asListed || swapped) << e.corner.x << ", " << e.corner.y;
        EXPECT_TRUE(region.contains(found->first));
        EXPECT_TRUE(region.contains(found->second));
    }
}

TEST(CornerSeeds, ShrinkUntilNeighbouringCirclesTouch) {
    // Two windows 0.6 m apart: their facing corners' PD circles would overlap at PD = 1.
    WallRegion region(WallFace{rectangle(0, 0, 10, 4), {rectangle(2, 1, 4, 3), rectangle(4.6, 1, 6.6, 3)}});
    for (const CornerSeeds &c : cornerSeeds(region, 1)) {
        bool facing = c.corner.x == 4 || c.corner.x == 4.6;
        EXPECT_NEAR(c.distance, facing ? 0.3 : 1, 1e-12) << c.corner.x << ", " << c.corner.y;
        EXPECT_NEAR(length(c.first - c.second), c.distance, 1e-12);
    }
}

TEST(ConvexPieces, SplitsConcaveAndHoledPiecesIntoConvexOnes) {
    RegionPiece ell{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}};
    RegionPiece ring{rectangle(0, 0, 3, 3), {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}};
    // Two squares meeting at the corner (1, 1), as CGAL's Boolean results may touch themselves: the
    // optimal convex partition's precondition refused it.
    RegionPiece pinched{{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}, {}};
    for (const RegionPiece &piece : {ell, ring, pinched}) {
        double total = 0;
        std::vector<std::vector<Vec2d>> parts = convexPieces(piece.outline, piece.holes);
        EXPECT_GE(parts.size(), 2u);
        for (const auto &part : parts) {
            EXPECT_TRUE(polygon(part).is_convex());
            EXPECT_GT(ringArea(part), 0);
            total += ringArea(part);
        }
        EXPECT_NEAR(total, area(piece), 1e-12);
    }
    EXPECT_EQ(convexPieces(rectangle(0, 0, 1, 1)).size(), 1u);
    // Repeated and collinear points are dropped; nothing with area is nothing.
    std::vector<std::vector<Vec2d>> square = convexPieces({{0, 0}, {0.5, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}});
    ASSERT_EQ(square.size(), 1u);
    EXPECT_EQ(square[0].size(), 4u);
    EXPECT_TRUE(convexPieces({{0, 0}, {1, 0}, {2, 0}}).empty());
}

// A wall element around its opening, an arched window whose jambs carry extra collinear points
// (as casings give them): the bands around the window's box and fans from its corners, which
// cover the element less the window once, every corner an input point.
TEST(ConvexPieces, AWallElementAroundAConvexOpeningIsItsBandsAndCornerFans) {
    std::vector<Vec2d> arch{{1, 0.8}, {1.6, 0.8}, {2.2, 0.8}, {2.2, 1.5}, {2.2, 2.2}};
    for (int k = 1; k < 12; ++k) {
        double angle = M_PI * k / 12;
        arch.push_back({1.6 + 0.6 * std::cos(angle), 2.2 + 0.6 * std::sin(angle)});
    }
    arch.insert(arch.end(), {{1, 2.2}, {1, 1.5}});
    for (bool clockwise : {false, true}) {
        std::vector<Vec2d> hole = arch;
        if (clockwise) std::reverse(hole.begin(), hole.end());
        std::vector<std::vector<Vec2d>> parts = convexPieces(rectangle(0, 0, 4, 3.5), {hole});
        // Four bands and a triangle for each of the arch's twelve edges (a triangulation: 19).
        EXPECT_EQ(parts.size(), 16u);
        double total = 0;
        for (const auto &part : parts) {
            EXPECT_TRUE(polygon(part).is_convex());
            EXPECT_GT(ringArea(part), 0);
            total += ringArea(part);
            for (Vec2d p : part) {
                bool x =
                    p.x == 0 || p.x == 4 || std::any_of(arch.begin(), arch.end(), [&](Vec2d q) { return q.x == p.x; });
                bool y = p.y == 0 || p.y == 3.5 ||
                    std::any_of(arch.begin(), arch.end(), [&](Vec2d q) { return q.y == p.y; });
                EXPECT_TRUE(x && y) << p.x << " " << p.y;
            }
        }
        EXPECT_NEAR(total, 4 * 3.5 - ringArea(arch), 1e-12);
        // Every point of the element less the window lies in exactly one piece.
        Polygon window = polygon(arch);
        for (double x = 0.013; x < 4; x += 0.05)
            for (double y = 0.017; y < 3.5; y += 0.05) {
                Kernel::Point_2 p(x, y);
                int in = 0;
                for (const auto &part : parts) in += polygon(part).bounded_side(p) == CGAL::ON_BOUNDED_SIDE;
                EXPECT_EQ(in, window.bounded_side(p) == CGAL::ON_UNBOUNDED_SIDE ? 1 : 0) << x << " " << y;
            }
    }
}

TEST(CyclopeanLayout, ClipsEveryCellConvexAroundDoorAndWindow) {
    WallRegion region(wallWithDoorAndWindow());
    CyclopeanLayout layout = layOutCyclopean(region, description(), 7, 11);
    EXPECT_DOUBLE_EQ(layout.radius, 0.25);
    // Hexagonal count of the 10 × 3 bounding wall (n1 20, n2 19, n_v 6: 117 → 94), times the
    // wall's 26.36 / 30 share.
    EXPECT_EQ(layout.targetCount, 83);
    ASSERT_EQ(layout.corners.size(), 6u);
    const LloydResult &relaxed = layout.relaxed;
    EXPECT_GT(relaxed.seeds.size(), 70u);
    EXPECT_LT(relaxed.seeds.size(), 100u);
    for (size_t i = 0; i < layout.corners.size(); ++i) {
        EXPECT_EQ(relaxed.seeds[2 * i], layout.corners[i].first);
        EXPECT_EQ(relaxed.seeds[2 * i + 1], layout.corners[i].second);
    }
    double total = 0;
    for (const ClippedCell &cell : relaxed.cells) {
        ASSERT_EQ(cell.size(), 1u);
        EXPECT_TRUE(cell[0].holes.empty());
        EXPECT_TRUE(polygon(cell[0].outline).is_convex());
        total += area(cell);
    }
    EXPECT_NEAR(total, region.area(), 1e-9);
}

TEST(CyclopeanLayout, RelaxesWithFallingShifts) {
    CyclopeanLayout layout = layOutCyclopean(WallRegion(wallWithDoorAndWindow()), description(), 7, 11);
    const std::vector<double> &shifts = layout.relaxed.meanShifts;
    ASSERT_EQ(shifts.size(), 30u);
    // What holds: the mean shift falls step by step after the first step, and by a factor 10 over
    // the 30 steps; the energy never rises.
    for (size_t i = 2; i < shifts.size(); ++i) EXPECT_LE(shifts[i], shifts[i - 1]) << "step " << i;
    EXPECT_LT(shifts.back(), shifts.front() / 10);
    const std::vector<double> &energies = layout.relaxed.energies;
    for (size_t i = 1; i < energies.size(); ++i) EXPECT_LE(energies[i], energies[i - 1] * (1 + 1e-12));
}

TEST(CyclopeanMasonry, LaysConvexStonesOutsideTheOpenings) {
    WallFace wall = wallWithDoorAndWindow();
    CyclopeanMasonry d = description();
    Masonry masonry = cyclopeanMasonry(wall, d, 7, 11);
    ASSERT_GT(masonry.stones.size(), 70u);
    EXPECT_EQ(masonry.mortarThickness, d.joint);
    Polygon outline = polygon(wall.outline);
    for (const Stone &stone : masonry.stones) {
        Polygon p = polygon(stone.outline);
        EXPECT_TRUE(p.is_convex());
        EXPECT_TRUE(p.is_counterclockwise_oriented());
        for (const auto &v : p.vertices()) EXPECT_EQ(outline.bounded_side(v), CGAL::ON_BOUNDED_SIDE);
        for (const auto &opening : wall.openings) EXPECT_FALSE(CGAL::do_intersect(p, polygon(opening)));
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(stone.colour[c], d.startColour[c]);
            EXPECT_LE(stone.colour[c], d.endColour[c]);
        }
        EXPECT_EQ(stone.depth, d.depth);
    }
}

TEST(CyclopeanMasonry, CoversTheWallUpToTheJoints) {
    WallFace wall = wallWithDoorAndWindow();
    CyclopeanMasonry d = description();
    WallRegion region(wall);
    CyclopeanLayout layout = layOutCyclopean(region, d, 7, 11);
    // Each cell loses at most its perimeter times the widest half joint (1.5 · joint / 2).
    double least = 0;
    for (const ClippedCell &cell : layout.relaxed.cells) {
        least += area(cell) - perimeter(cell[0].outline) * 0.75 * d.joint;
    }
    double stones = 0;
    for (const Stone &stone : cyclopeanMasonry(wall, d, 7, 11).stones) stones += ringArea(stone.outline);
    EXPECT_GE(stones, least);
    EXPECT_LT(stones, region.area());
    // And loses at least a quarter joint along every cell edge: half the perimeter times it, less
    // the corners' overlap, is more than 2 % of this wall.
    EXPECT_LT(stones, region.area() * 0.98);
}

TEST(CyclopeanMasonry, LaysConvexStonesWhereTwoOpeningsMeetAtACorner) {
    // The cells round (2.5, 2.5) are clipped into pieces touching themselves at that corner, which
    // the optimal convex partition refused (a CGAL precondition failure) for every seed.
    WallFace wall{rectangle(0, 0, 6, 5), {rectangle(1, 1, 2.5, 2.5), rectangle(2.5, 2.5, 4, 4)}};
    for (uint32_t seed = 0; seed < 3; ++seed) {
        Masonry masonry = cyclopeanMasonry(wall, description(), seed, 1);
        ASSERT_GT(masonry.stones.size(), 40u);
        for (const Stone &stone : masonry.stones) EXPECT_TRUE(polygon(stone.outline).is_convex());
    }
}

TEST(CyclopeanMasonry, AThinFrameRoundALargeOpeningSpreadsItsSeedsOverFewCells) {
    // A micrometre of wall round a 100 m opening: cells of the wall's area share were 0.009 m wide,
    // 10^8 of them, each measured against every ring (minutes); at most 16 per stone now.
    WallFace wall{rectangle(0, 0, 100, 100), {rectangle(1e-6, 1e-6, 100 - 1e-6, 100 - 1e-6)}};
    CyclopeanMasonry d = description();
    d.spacing = 0;
    d.stones = 20;
    d.joint = 0;
    WallRegion region(wall);
    Masonry masonry = cyclopeanMasonry(wall, d, 7, 11);
    double stones = 0;
    for (const Stone &stone : masonry.stones) {
        for (Vec2d p : stone.outline) EXPECT_TRUE(p.x >= 0 && p.x <= 100 && p.y >= 0 && p.y <= 100);
        stones += ringArea(stone.outline);
    }
    EXPECT_LE(stones, region.area() * (1 + 1e-9));
}

TEST(CyclopeanMasonry, IsTheSameForASeedAndDiffersAcrossSeeds) {
    WallFace wall = wallWithDoorAndWindow();
    Masonry first = cyclopeanMasonry(wall, description(), 7, 11);
    Masonry again = cyclopeanMasonry(wall, description(), 7, 11);
    ASSERT_EQ(first.stones.size(), again.stones.size());
    for (size_t i = 0; i < first.stones.size(); ++i) {
        EXPECT_EQ(first.stones[i].outline, again.stones[i].outline);
        EXPECT_EQ(first.stones[i].colour, again.stones[i].colour);
    }
    Masonry otherWall = cyclopeanMasonry(wall, description(), 7, 12);
    EXPECT_NE(first.stones.back().outline, otherWall.stones.back().outline);
}

TEST(CyclopeanMasonry, TakesAStoneCountInsteadOfASpacing) {
    CyclopeanMasonry d = description();
    d.spacing = 0;
    d.stones = 40;
    WallRegion region(wallWithDoorAndWindow());
    CyclopeanLayout layout = layOutCyclopean(region, d, 1, 2);
    EXPECT_EQ(layout.targetCount, 40);
    EXPECT_NEAR(layout.radius, std::sqrt(0.8 * region.area() / (2 * std::sqrt(3.0) * 40)), 1e-12);
    // Equal seeds per grid cell and the corners' pairs meet the count within 30 %.
    EXPECT_GT(layout.relaxed.seeds.size(), 28u);
    EXPECT_LT(layout.relaxed.seeds.size(), 52u);
}

TEST(CyclopeanMasonry, RefusesUnusableDescriptionsAtTheirPlace) {
    CyclopeanMasonry both = description();
    both.stones = 10;
    EXPECT_EQ(errorOf(both),
              "wall.txt:4:2: a cyclopean wall needs either a stone count (Steine) or a spacing "
              "(Abstand) above 0");
    CyclopeanMasonry fine = description();
    fine.spacing = 0.01;
    EXPECT_EQ(errorOf(fine),
              "wall.txt:4:2: a spacing of 0.01 m puts 243094 stones on a 10 × 3 m wall, more than the "
              "20000 allowed");
    CyclopeanMasonry many = description();
    many.spacing = 0;
    many.stones = 20001;
    EXPECT_EQ(errorOf(many), "wall.txt:4:2: 20001 stones on a cyclopean wall are more than the 20000 allowed");
    CyclopeanMasonry steps = description();
    steps.lloyd = -1;
    EXPECT_EQ(errorOf(steps), "wall.txt:4:2: Lloyd steps must lie in 0..1000, not -1");
    CyclopeanMasonry colour = description();
    colour.endColour = {1.5f, 0, 0};
    EXPECT_EQ(errorOf(colour), "wall.txt:4:2: colours must lie in [0, 1]");
}

std::string parseErrorOf(const std::string &text) {
    try {
        parseCyclopeanMasonry(text, "c.txt");
    } catch (const InputError &error) {
        return error.what();
    }
    return "no error";
}

TEST(CyclopeanMasonryText, ReadsSpacingOrStonesColoursJointAndDepth) {
    CyclopeanMasonry d = parseCyclopeanMasonry(
        "# a field-stone wall\nCyclopeanMasonry { spacing, 0.8; 30; 0,0,0; 255,255,255; 0.03; 188,188,188; 0.02; }",
        "c.txt");
    EXPECT_EQ(d.spacing, 0.8);
    EXPECT_EQ(d.stones, 0);
    EXPECT_EQ(d.lloyd, 30);
    EXPECT_EQ(d.startColour, (Vec3f{0, 0, 0}));
    EXPECT_EQ(d.endColour, (Vec3f{1, 1, 1}));
    // 8-bit sRGB 188 is linear ((188/255 + 0.055) / 1.055)^2.4 = 0.5029.
    EXPECT_NEAR(d.mortarColour.x, 0.5029, 1e-4);
    EXPECT_EQ(d.joint, 0.03);
    EXPECT_EQ(d.depth, 0.02);
    EXPECT_EQ(d.loc.toString(), "c.txt:2:1");
    CyclopeanMasonry counted =
        parseCyclopeanMasonry("CyclopeanMasonry { stones, 120; 0; 1,2,3; 4,5,6; 0; 7,8,9; 0; }", "c.txt");
    EXPECT_EQ(counted.stones, 120);
    EXPECT_EQ(counted.spacing, 0);
    EXPECT_EQ(counted.lloyd, 0);
    // What it reads, the layout takes.
    EXPECT_GT(cyclopeanMasonry(wallWithDoorAndWindow(), d, 1, 2).stones.size(), 10u);
}

TEST(CyclopeanMasonryText, RefusesBadTextsAtTheirPlace) {
    const std::string tail = "; 30; 0,0,0; 9,9,9; 0.03; 9,9,9; 0.02; }";
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 20001" + tail),
              "c.txt:1:28: the stone count 20001 is not a whole number from 1 to 20000");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 2.5" + tail),
              "c.txt:1:28: the stone count 2.5 is not a whole number from 1 to 20000");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { spacing, 0" + tail),
              "c.txt:1:29: the spacing 0 is outside (0, 10000] m");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { Steine, 10" + tail),
              "c.txt:1:20: expected 'spacing' or 'stones', found 'Steine'");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 10; 1001; 0,0,0; 9,9,9; 0.03; 9,9,9; 0.02; }"),
              "c.txt:1:32: the Lloyd steps 1001 is not a whole number from 0 to 1000");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 10; 1; 0,0,0; 9,9,9; -0.03; 9,9,9; 0.02; }"),
              "c.txt:1:49: the joint -0.03 is outside [0, 10000] m");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 10; 1; 0,0,256; 9,9,9; 0.03; 9,9,9; 0.02; }"),
              "c.txt:1:39: the stones' start colour: 256 is not a whole number from 0 to 255");
    EXPECT_EQ(parseErrorOf("CyclopeanMasonry { stones, 10; 1; 0,0,0; 9,9,9; 0.03; 9,9,9; }"),
              "c.txt:1:1: CyclopeanMasonry takes 7 items (spacing or stones; Lloyd steps; start colour; end colour; "
              "joint; mortar colour; depth), found 6");
    EXPECT_EQ(parseErrorOf("Zyklopen { }"),
              "c.txt:1:1: expected one block, named 'CyclopeanMasonry', found 'Zyklopen'");
    EXPECT_EQ(parseErrorOf(""), "c.txt:1:1: the description has no block named 'CyclopeanMasonry'");
}

}  // namespace
}  // namespace veduta
