#include "facade/brick_bond.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/minkowski_sum_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/polygon_area.h"
#include "input_error.h"
#include "thesis_figures.h"

namespace veduta {
namespace {

using thesis::kFigure5_7;

using test::inputErrorOf;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

// One brick in a stack bond: every brick of a course exactly over one of the course below.
constexpr const char *kStackBond = R"(B { 2.0, 0.5, 0.1; 100,100,100; 200,200,200; }
P { 0, "B"; }
BrickMasonry { "P"; 0.05; 90,90,90; })";

std::vector<Vec2d> rectangle(double lowX, double lowY, double highX, double highY) {
    return {{lowX, lowY}, {highX, lowY}, {highX, highY}, {lowX, highY}};
}

double brickArea(const Masonry &masonry) {
    double total = 0;
    for (const Stone &stone : masonry.stones) total += signedArea(stone.outline);
    return total;
}

ExactPolygon toExact(const std::vector<Vec2d> &points) {
    ExactPolygon polygon;
    for (Vec2d p : points) polygon.push_back(Kernel::Point_2(p.x, p.y));
    return polygon;
}

double exactOverlap(const ExactPolygon &a, const ExactPolygonWithHoles &b) {
    std::vector<ExactPolygonWithHoles> parts;
    CGAL::intersection(ExactPolygonWithHoles(a), b, std::back_inserter(parts));
    double overlap = 0;
    for (const auto &part : parts) overlap += CGAL::to_double(part.outer_boundary().area());
    return overlap;
}

bool boxesOverlap(const CGAL::Bbox_2 &a, const CGAL::Bbox_2 &b) {
    return a.xmin() < b.xmax() && b.xmin() < a.xmax() && a.ymin() < b.ymax() && b.ymin() < a.ymax();
}

// A 5 m × 3 m wall with a window and a door with a gabled head (house-shaped, its slopes at 45°).
WallFace testWall() {
    return {rectangle(0, 0, 5, 3),
            {rectangle(0.8, 1.0, 1.9, 2.3), {{3.0, 0.0}, {4.0, 0.0}, {4.0, 2.0}, {3.5, 2.5}, {3.0, 2.0}}}};
}

TEST(BrickBond, Figure5_7ParsesWithCourseOffsetsMinusOneMinusOneZero) {
    // §8 row 13 reads "course offsets −1, −1, 0" for the listed versatz −1.0, 0.0, 1.0: the first
    // course's offset is its own (−1), each next one is relative to the course listed before it,
    // −1 + 0 = −1 and −1 + 1 = 0. The offsets are the courses' as listed, top to bottom.
    BrickBond bond = parseBrickBond(kFigure5_7, "fig5_7.txt");
    ASSERT_EQ(bond.courses.size(), 3u);
    EXPECT_EQ(bond.courses[0].offset, -1.0);
    EXPECT_EQ(bond.courses[1].offset, -1.0);
    EXPECT_EQ(bond.courses[2].offset, 0.0);
    ASSERT_EQ(bond.bricks.size(), 2u);
    EXPECT_EQ(bond.bricks[1].name, "Brick2");
    EXPECT_EQ(bond.bricks[0].colour.start, Vec3f(206, 78, 51));
    EXPECT_EQ(bond.mortarThickness, 0.05);
    EXPECT_EQ(bond.mortarColour, Vec3f(102, 102, 102));
    for (const BondCourse &course : bond.courses) EXPECT_EQ(course.height, 0.5);
    EXPECT_DOUBLE_EQ(bond.courses[0].length, 4.1);
    EXPECT_DOUBLE_EQ(bond.courses[1].length, 4.1);
    EXPECT_DOUBLE_EQ(bond.courses[2].length, 2.05);
    // Brick2 (armiert) spans its course and the next one's gap: 0.5 + 0.05 + 0.5.
    const BondUnit &tall = bond.courses[0].units[1];
    EXPECT_EQ(tall.spans, 2);
    EXPECT_DOUBLE_EQ(tall.height, 1.05);
    EXPECT_EQ(bond.courses[1].units[1].brick, -1);
    EXPECT_EQ(bond.courses[1].units[1].length, 2.0);
}

TEST(BrickBond, Figure5_7LaysItsTallBricksIntoTheGapsBelowThem) {
    Masonry masonry = layBrickBond(parseBrickBond(kFigure5_7, ""), {rectangle(0, 0, 8.2, 3.3), {}}, {1, 7, 3});
    // From the bottom: course 3 (offset 0), course 2 (−1, gap at 1.05 + 4.1 k), course 1 (−1, Brick2
    // from y 1.6 down to 0.55 at 1.05 + 4.1 k), then again.
    int tall = 0;
    for (const Stone &stone : masonry.stones) {
        Vec2d low = stone.outline[0], high = stone.outline[0];
        for (Vec2d p : stone.outline) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y)};
        }
        double height = high.y - low.y;
        if (std::abs(height - 1.05) > 1e-9) {
            EXPECT_NEAR(height, 0.5, 1e-9);
            continue;
        }
        ++tall;
        EXPECT_NEAR(std::remainder(low.x - 1.05, 4.1), 0, 1e-9);
        EXPECT_NEAR(std::remainder(low.y - 0.55, 1.65), 0, 1e-9);
    }
    EXPECT_EQ(tall, 4);  // two per period of three courses, two periods
    EXPECT_NEAR(masonry.mortarThickness, 0.05, 1e-15);
}

TEST(BrickBond, NoBrickEntersAnOpeningGrownByTheMortar) {
    double scale = 0.125, mortar = 0.05 * scale;
    WallFace wall = testWall();
    Masonry masonry = layBrickBond(parseBrickBond(kFigure5_7, ""), wall, {scale, 1, 2});
    ASSERT_GT(masonry.stones.size(), 500u);
    ExactPolygon square = toExact(rectangle(-mortar, -mortar, mortar, mortar));
    int checked = 0;
    for (const auto &opening : wall.openings) {
        ExactPolygonWithHoles grown = CGAL::minkowski_sum_2(toExact(opening), square);
        CGAL::Bbox_2 bounds = grown.outer_boundary().bbox();
        for (const Stone &stone : masonry.stones) {
            ExactPolygon brick = toExact(stone.outline);
            if (!boxesOverlap(brick.bbox(), bounds)) continue;
            ++checked;
            EXPECT_LE(exactOverlap(brick, grown), 1e-15);  // the stones' corners are rounded to double
        }
    }
    EXPECT_GT(checked, 20);
}

TEST(BrickBond, BricksNeverOverlapAndStayInTheWall) {
    double scale = 0.125;
    Masonry masonry = layBrickBond(parseBrickBond(kFigure5_7, ""), testWall(), {scale, 1, 2});
    std::vector<ExactPolygon> bricks;
    for (const Stone &stone : masonry.stones) {
        for (Vec2d p : stone.outline) {
            EXPECT_TRUE(p.x >= 0 && p.x <= 5 && p.y >= 0 && p.y <= 3);
        }
        EXPECT_GT(signedArea(stone.outline), 0);  // counter-clockwise
        EXPECT_NEAR(stone.depth, 0.1 * scale, 1e-15);
        bricks.push_back(toExact(stone.outline));
    }
    for (size_t i = 0; i < bricks.size(); ++i) {
        for (size_t j = i + 1; j < bricks.size(); ++j) {
            if (!boxesOverlap(bricks[i].bbox(), bricks[j].bbox())) continue;
            EXPECT_LE(exactOverlap(bricks[i], ExactPolygonWithHoles(bricks[j])), 1e-15) << i << " " << j;
        }
    }
}

TEST(BrickBond, BricksAndMortarTileTheWallMinusItsOpenings) {
    // Stack bond on a wall of 10 repetitions × 6 courses (20.5 × 3.3): 60 bricks of 2 × 0.5.
    BrickBond bond = parseBrickBond(kStackBond, "");
    WallFace wall{rectangle(0, 0, 20.5, 3.3), {}};
    Masonry whole = layBrickBond(bond, wall, {1, 0, 0});
    EXPECT_EQ(whole.stones.size(), 60u);
    EXPECT_NEAR(brickArea(whole), 60, 1e-9);
    // A window whose grown outline [2.05, 6.15] × [0.55, 1.65] is exactly four bricks and their
    // joints: the rest is untouched.
    wall.openings = {rectangle(2.1, 0.6, 6.1, 1.6)};
    Masonry aligned = layBrickBond(bond, wall, {1, 0, 0});
    EXPECT_EQ(aligned.stones.size(), 56u);
    EXPECT_NEAR(brickArea(aligned), 56, 1e-9);
    // Grown to x in [3, 7]: in two courses the bricks at 2.05 and 6.15 are cut to 0.95 and 1.15 long
    // and the one between goes: 2 × 0.5 × (2 − 0.95 + 2 + 2 − 1.15) = 3.9 less brick.
    wall.openings = {rectangle(3.05, 0.6, 6.95, 1.6)};
    Masonry cut = layBrickBond(bond, wall, {1, 0, 0});
    EXPECT_EQ(cut.stones.size(), 58u);
    EXPECT_NEAR(brickArea(cut), 60 - 3.9, 1e-9);
    // The mortar is the rest: wall minus grown opening minus bricks = the joints of a whole wall
    // (67.65 − 60) less those inside the grown opening (3.9 × 1.1 − 2 × 0.5 × 3.9 ... as laid).
    double mortar = 20.5 * 3.3 - 3.9 * 1.1 - brickArea(cut);
    EXPECT_NEAR(mortar, 7.65 - (3.9 * 1.1 - 3.9), 1e-9);
}

TEST(BrickBond, ColoursStayWithinTheirRanges) {
    Masonry masonry = layBrickBond(parseBrickBond(kFigure5_7, ""), testWall(), {0.125, 5, 9});
    Vec3f low = ColourRange{{206, 78, 51}, {206, 78, 51}}.at(0);
    Vec3f high = ColourRange{{255, 147, 124}, {255, 147, 124}}.at(0);
    EXPECT_NEAR(low.x, 0.617, 0.001);  // sRGB 206 decoded
    EXPECT_EQ(high.x, 1.0f);
    Vec3f mean;
    for (const Stone &stone : masonry.stones) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(stone.colour[c], low[c]);
            EXPECT_LE(stone.colour[c], high[c]);
        }
        mean += stone.colour * (1.0f / float(masonry.stones.size()));
    }
    // Spread over the range, not stuck at one end.
    EXPECT_GT(mean.y, low.y + 0.25f * (high.y - low.y));
    EXPECT_LT(mean.y, low.y + 0.75f * (high.y - low.y));
    EXPECT_EQ(masonry.mortarColour, (ColourRange{{102, 102, 102}, {}}.at(0)));
    EXPECT_NEAR(masonry.mortarColour.x, 0.1329, 0.0001);
}

TEST(BrickBond, TheSameSeedLaysTheSameWallAndAnotherSeedOtherColours) {
    BrickBond bond = parseBrickBond(kFigure5_7, "");
    Masonry a = layBrickBond(bond, testWall(), {0.125, 11, 4});
    Masonry b = layBrickBond(bond, testWall(), {0.125, 11, 4});
    Masonry c = layBrickBond(bond, testWall(), {0.125, 12, 4});
    Masonry d = layBrickBond(bond, testWall(), {0.125, 11, 5});
    ASSERT_EQ(a.stones.size(), b.stones.size());
    ASSERT_EQ(a.stones.size(), c.stones.size());
    size_t sameAsC = 0, sameAsD = 0;
    for (size_t i = 0; i < a.stones.size(); ++i) {
        EXPECT_EQ(a.stones[i].outline, b.stones[i].outline);
        EXPECT_EQ(a.stones[i].colour, b.stones[i].colour);
        EXPECT_EQ(a.stones[i].outline, c.stones[i].outline);  // the bond does not depend on the seed
        sameAsC += a.stones[i].colour == c.stones[i].colour;
        sameAsD += a.stones[i].colour == d.stones[i].colour;
    }
    EXPECT_LT(sameAsC, a.stones.size() / 100);
    EXPECT_LT(sameAsD, a.stones.size() / 100);
}

std::string errorOf(const std::string &text) {
    return inputErrorOf([&] { parseBrickBond(text, "bond.txt"); });
}

TEST(BrickBond, BadDescriptionsAreReportedWithTheirPlace) {
    const std::string brick = "B { 2, 0.5, 0.1; 1,2,3; 4,5,6; }\n";
    const std::string masonry = "BrickMasonry { \"P\"; 0.05; 9,9,9; }\n";
    EXPECT_EQ(errorOf(brick + "P { 0, \"B\"; }\n"), "bond.txt:1:1: the description has no block named 'BrickMasonry'");
    EXPECT_EQ(errorOf(brick + "P { 0, \"C\"; }\n" + masonry), "bond.txt:2:8: no block named 'C'");
    EXPECT_EQ(errorOf(brick + "P { 0, B; }\n" + masonry),
              "bond.txt:2:8: expected a brick's name or a gap length (a quoted string), found a word 'B'");
    EXPECT_EQ(errorOf("B { 2, 0.5, 0.1; 1,256,3; 4,5,6; }\nP { 0, \"B\"; }\n" + masonry),
              "bond.txt:1:20: a brick's start colour: 256 is not a whole number from 0 to 255");
    EXPECT_EQ(errorOf("B { 2, 0.5, 0.1; 1,2,3; 4,5,6.5; }\nP { 0, \"B\"; }\n" + masonry),
              "bond.txt:1:29: a brick's end colour: 6.5 is not a whole number from 0 to 255");
    EXPECT_EQ(errorOf("B { 2, 0, 0.1; 1,2,3; 4,5,6; }\nP { 0, \"B\"; }\n" + masonry),
              "bond.txt:1:8: a brick's length, height and depth: the height is not positive");
    EXPECT_EQ(errorOf("B { 2, 0.5; 1,2,3; 4,5,6; }\nP { 0, \"B\"; }\n" + masonry),
              "bond.txt:1:5: a brick's length, height and depth takes 3 fields, found 2");
    EXPECT_EQ(errorOf(brick + "P { 0, \"B\", -1; }\n" + masonry), "bond.txt:2:13: a gap of -1 is not positive");
    EXPECT_EQ(errorOf(brick + "P { 0, \"B\"; 0, 2.0; }\n" + masonry),
              "bond.txt:2:13: a course needs at least one brick");
    EXPECT_EQ(errorOf(brick + "P { 0; }\n" + masonry),
              "bond.txt:2:5: a course takes its offset and at least one brick or gap");
    EXPECT_EQ(errorOf(brick + "X { 1; }\nP { 0, \"B\"; }\n" + masonry),
              "bond.txt:2:1: the block 'X' is not used by the BrickMasonry");
    EXPECT_EQ(errorOf(brick + brick + "P { 0, \"B\"; }\n" + masonry),
              "bond.txt:2:1: a second block named 'B' (the first is on line 1)");
    EXPECT_EQ(errorOf(brick + "P { 0, \"B\"; }\nBrickMasonry { \"P\"; -0.05; 9,9,9; }"),
              "bond.txt:3:21: the mortar thickness is negative");
    // Brick2 of Fig. 5.7 with no gap under it: the second course lays a brick there.
    EXPECT_EQ(errorOf("Brick1 { 2.0, 0.5, 0.1; 1,1,1; 2,2,2; }\nBrick2 { 2.0, 1.0, 0.1; 1,1,1; 2,2,2; }\n"
                      "Pattern { -1.0, \"Brick1\", \"Brick2\"; 0.0, \"Brick1\", \"Brick1\"; }\n"
                      "BrickMasonry { \"Pattern\"; 0.05; 102,102,102; }"),
              "bond.txt:3:27: the brick 'Brick2' reaches down into the course on line 3, which has no gap under it");
    EXPECT_EQ(errorOf("Brick1 { 2.0, 0.5, 0.1; 1,1,1; 2,2,2; }\nBrick2 { 2.0, 1.0, 0.1; 1,1,1; 2,2,2; }\n"
                      "Pattern { -1.0, \"Brick1\", \"Brick2\"; 1.0, \"Brick1\"; }\n"
                      "BrickMasonry { \"Pattern\"; 0.05; 102,102,102; }"),
              "bond.txt:3:27: the brick 'Brick2' reaches down into the course on line 3, whose repetition (2.05) is "
              "not as long as its own (4.1)");
}

TEST(BrickBond, LengthsAndMortarBeyondTheLimitAreReportedAtTheirField) {
    // Unbounded, 1e300 summed along a course made its length infinite and the layout ran on ±inf.
    const std::string masonry = "BrickMasonry { \"P\"; 0.05; 9,9,9; }\n";
    const std::string pattern = "P { 0, \"B\"; }\n";
    EXPECT_EQ(errorOf("B { 1e300, 0.5, 0.1; 1,2,3; 4,5,6; }\n" + pattern + masonry),
              "bond.txt:1:5: a brick's length, height and depth: the length 1e300 is above the 10000 units allowed");
    EXPECT_EQ(errorOf("B { 2, 0.5, 20000; 1,2,3; 4,5,6; }\n" + pattern + masonry),
              "bond.txt:1:13: a brick's length, height and depth: the depth 20000 is above the 10000 units allowed");
    const std::string brick = "B { 2, 0.5, 0.1; 1,2,3; 4,5,6; }\n";
    EXPECT_EQ(errorOf(brick + "P { 0, \"B\", 1e200; }\n" + masonry),
              "bond.txt:2:13: a gap of 1e200 is above the 10000 units allowed");
    EXPECT_EQ(errorOf(brick + "P { -1e20, \"B\"; }\n" + masonry),
              "bond.txt:2:5: the course's offset -1e20 is beyond the ±10000 units allowed");
    EXPECT_EQ(errorOf(brick + pattern + "BrickMasonry { \"P\"; 1e300; 9,9,9; }"),
              "bond.txt:3:21: the mortar thickness 1e300 is above the 10000 units allowed");
    EXPECT_EQ(errorOf(brick + pattern + "BrickMasonry { \"P\"; 10000; 9,9,9; }"), "no error");
}

TEST(BrickBond, ScaledSizesThatDoNotSuitTheWallAreRefusedAtTheBlock) {
    BrickBond bond = parseBrickBond(kStackBond, "bond.txt");
    // The mortar in metres overflowed to inf and reached WallMask's internal check.
    bond.mortarThickness = kMasonryLengthLimit;
    EXPECT_EQ(inputErrorOf([&] {
                  layBrickBond(bond, {rectangle(0, 0, 4, 3), {}}, {1e305, 0, 0});
              }),
              "bond.txt:3:1: the masonry's sizes are not finite in metres");
    bond = parseBrickBond(kStackBond, "bond.txt");
    EXPECT_EQ(inputErrorOf([&] {
                  layBrickBond(bond, {rectangle(0, 0, 4, 3), {}}, {1e300, 0, 0});
              }),
              "bond.txt:3:1: a size of 2.05e+300 m is out of all proportion to a wall of 4 × 3 m");
    // Bricks of 0.5 µm a kilometre from the origin: adding one would barely move the walk.
    EXPECT_EQ(inputErrorOf([&] {
                  layBrickBond(bond, {rectangle(1e3, 0, 1e3 + 1e-5, 1e-5), {}}, {1e-6, 0, 0});
              }),
              "bond.txt:3:1: stones of 5e-07 m are too small to lay on a wall reaching 1000.00001 m from the origin");
}

TEST(BrickBond, AWallThatWouldTakeTooManyBricksIsRefused) {
    BrickBond bond = parseBrickBond(kStackBond, "bond.txt");
    EXPECT_EQ(inputErrorOf([&] {
                  layBrickBond(bond, {rectangle(0, 0, 1000, 1000), {}}, {0.001, 0, 0});
              }),
              "bond.txt:3:1: the bond would lay more than 1048576 bricks on a wall of 1000 × 1000 m");
}

}  // namespace
}  // namespace veduta
