#include "facade/ashlar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "input_error.h"

namespace veduta {
namespace {

using test::inputErrorOf;

// digest-001 §2.5, Def 5.8's example (L1072).
constexpr const char *kThesisExample = R"(AshlarMasonry { 0.5, 0.5, 0.05; 1.5, 0.5, 0.1; 80, 80, 80;
    100, 100, 90; 0.05; 110, 110, 110; })";
// Courses of different heights, for walls with openings.
constexpr const char *kVariedCourses = R"(AshlarMasonry { 0.5, 0.4, 0.05; 1.5, 0.6, 0.1; 80, 80, 80;
    100, 100, 90; 0.05; 110, 110, 110; })";

std::vector<Vec2d> rectangle(double lowX, double lowY, double highX, double highY) {
    return {{lowX, lowY}, {highX, lowY}, {highX, highY}, {lowX, highY}};
}

struct Box {
    Vec2d low{1e300, 1e300}, high{-1e300, -1e300};
};

Box boxOf(const std::vector<Vec2d> &polygon) {
    Box box;
    for (Vec2d p : polygon) {
        box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y)};
        box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y)};
    }
    return box;
}

// Four corners, each edge along an axis.
bool isRectangle(const std::vector<Vec2d> &polygon) {
    if (polygon.size() != 4) return false;
    for (size_t i = 0; i < 4; ++i) {
        Vec2d a = polygon[i], b = polygon[(i + 1) % 4];
        if (a.x != b.x && a.y != b.y) return false;
    }
    return true;
}

bool isConvex(const std::vector<Vec2d> &polygon) {
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()], c = polygon[(i + 2) % polygon.size()];
        if (cross(b - a, c - b) < -1e-12) return false;
    }
    return polygon.size() >= 3;
}

// The calliper width: over the edges, the least greatest distance of a vertex from the edge's line.
double width(const std::vector<Vec2d> &convex) {
    double narrowest = 1e300;
    for (size_t i = 0; i < convex.size(); ++i) {
        Vec2d a = convex[i], edge = convex[(i + 1) % convex.size()] - a;
        double widest = 0;
        for (Vec2d p : convex) widest = std::max(widest, cross(edge, p - a) / length(edge));
        narrowest = std::min(narrowest, widest);
    }
    return narrowest;
}

// Andrew's monotone chain, counter-clockwise.
std::vector<Vec2d> convexHull(std::vector<Vec2d> points) {
    std::sort(points.begin(), points.end(), [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2d> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// Whether two convex polygons overlap by more than `tolerance` (separating axis test).
bool overlap(const std::vector<Vec2d> &a, const std::vector<Vec2d> &b, double tolerance) {
    for (const auto *polygon : {&a, &b}) {
        for (size_t i = 0; i < polygon->size(); ++i) {
            Vec2d edge = (*polygon)[(i + 1) % polygon->size()] - (*polygon)[i];
            Vec2d axis{-edge.y / length(edge), edge.x / length(edge)};
            double lowA = 1e300, highA = -1e300, lowB = 1e300, highB = -1e300;
            for (Vec2d p : a) lowA = std::min(lowA, dot(p, axis)), highA = std::max(highA, dot(p, axis));
            for (Vec2d p : b) lowB = std::min(lowB, dot(p, axis)), highB = std::max(highB, dot(p, axis));
            if (highA <= lowB + tolerance || highB <= lowA + tolerance) return false;
        }
    }
    return true;
}

TEST(Ashlar, TheThesisExampleParses) {
    AshlarMasonry ashlar = parseAshlarMasonry(kThesisExample, "ashlar.txt");
    EXPECT_EQ(ashlar.minSize.length, 0.5);
    EXPECT_EQ(ashlar.minSize.depth, 0.05);
    EXPECT_EQ(ashlar.maxSize.length, 1.5);
    EXPECT_EQ(ashlar.maxSize.height, 0.5);
    EXPECT_EQ(ashlar.colour.end, Vec3f(100, 100, 90));
    EXPECT_EQ(ashlar.mortarThickness, 0.05);
    EXPECT_EQ(ashlar.mortarColour, Vec3f(110, 110, 110));
}

TEST(Ashlar, WholeStonesOfAPlainWallLieWithinTheirSizeRange) {
    // The thesis's example at 0.5 m per unit: stones 0.25–0.75 m long, 0.25 m high, joints 0.025 m;
    // a wall of exactly eight courses, so every stone is whole except a short rest closing a course.
    double scale = 0.5;
    Masonry masonry = layAshlar(parseAshlarMasonry(kThesisExample, ""), {rectangle(0, 0, 6, 8 * 0.25 + 7 * 0.025), {}},
                                {scale, 3, 8});
    std::map<long, std::vector<Box>> courses;
    for (const Stone &stone : masonry.stones) {
        ASSERT_TRUE(isRectangle(stone.outline));
        Box box = boxOf(stone.outline);
        EXPECT_NEAR(box.high.y - box.low.y, 0.25, 1e-12);
        EXPECT_GE(stone.depth, 0.05 * scale);
        EXPECT_LE(stone.depth, 0.1 * scale);
        courses[std::lround(box.low.y / 0.275)].push_back(box);
    }
    ASSERT_EQ(courses.size(), 8u);
    for (auto &[course, boxes] : courses) {
        std::sort(boxes.begin(), boxes.end(), [](Box a, Box b) { return a.low.x < b.low.x; });
        EXPECT_EQ(boxes.front().low.x, 0);
        for (size_t i = 0; i < boxes.size(); ++i) {
            double length = boxes[i].high.x - boxes[i].low.x;
            EXPECT_LE(length, 0.75 + 1e-12);
            if (i + 1 < boxes.size()) {
                EXPECT_GE(length, 0.25 - 1e-12) << "course " << course << " stone " << i;
                EXPECT_NEAR(boxes[i + 1].low.x - boxes[i].high.x, 0.025, 1e-12);
            } else {
                EXPECT_GE(length, 0.5 * 0.25 - 1e-12);  // a cut rest no narrower than the least piece
            }
        }
    }
}

TEST(Ashlar, StonesAroundOpeningsAreConvexNotTooSmallAndKeepClearOfTheJoints) {
    double mortar = 0.05;
    // A gable wall with a window and a door with a gabled head (convex, so its grown outline is
    // the union of the opening and its joint, tested by separating axes).
    WallFace wall{{{0, 0}, {8, 0}, {8, 4}, {4, 6}, {0, 4}},
                  {rectangle(1, 1.2, 2.5, 3.1), {{5, 0}, {6.2, 0}, {6.2, 2.2}, {5.6, 2.8}, {5, 2.2}}}};
    Masonry masonry = layAshlar(parseAshlarMasonry(kVariedCourses, ""), wall, {1, 21, 2});
    ASSERT_GT(masonry.stones.size(), 40u);
    // The openings are convex, so grown by the square of half-side `mortar` they are the hulls of
    // their corners moved by the square's.
    std::vector<std::vector<Vec2d>> grown;
    for (const auto &opening : wall.openings) {
        std::vector<Vec2d> corners;
        for (Vec2d p : opening) {
            for (Vec2d d :
                 {Vec2d{-mortar, -mortar}, Vec2d{mortar, -mortar}, Vec2d{mortar, mortar}, Vec2d{-mortar, mortar}})
                corners.push_back(p + d);
        }
        grown.push_back(convexHull(corners));
    }
    size_t cut = 0;
    for (size_t i = 0; i < masonry.stones.size(); ++i) {
        const auto &outline = masonry.stones[i].outline;
        EXPECT_TRUE(isConvex(outline)) << i;
        EXPECT_GE(width(outline), 0.5 * 0.4 - 1e-12) << i;
        if (isRectangle(outline)) {
            Box box = boxOf(outline);
            EXPECT_LE(box.high.x - box.low.x, 1.5 + 1e-12);
            EXPECT_LE(box.high.y - box.low.y, 0.6 + 1e-12);
        } else {
            ++cut;
        }
        for (Vec2d p : outline) EXPECT_TRUE(p.x >= 0 && p.x <= 8 && p.y >= 0 && p.y <= 6);
        for (const auto &hull : grown) EXPECT_FALSE(overlap(outline, hull, 1e-12)) << i;
        for (size_t j = i + 1; j < masonry.stones.size(); ++j) {
            EXPECT_FALSE(overlap(outline, masonry.stones[j].outline, 1e-12)) << i << " " << j;
        }
    }
    EXPECT_GT(cut, 5u);
}

TEST(Ashlar, CutStonesStayConvexWhereTwoGrownOpeningsMeetAtACorner) {
    // Grown by the mortar, the two windows touch at (2.55, 2.55): a stone cut there is one piece
    // touching itself at that corner, which CGAL's optimal convex partition refused (a
    // precondition failure) for every seed.
    double mortar = 0.05;
    WallFace wall{rectangle(0, 0, 6, 5),
                  {rectangle(1, 1, 2.5, 2.5), rectangle(2.5 + 2 * mortar, 2.5 + 2 * mortar, 4, 4)}};
    AshlarMasonry ashlar = parseAshlarMasonry(kVariedCourses, "");
    for (uint32_t seed = 0; seed < 4; ++seed) {
        Masonry masonry = layAshlar(ashlar, wall, {1, seed, 1});
        ASSERT_GT(masonry.stones.size(), 20u);
        for (const Stone &stone : masonry.stones) {
            EXPECT_TRUE(isConvex(stone.outline));
            EXPECT_GE(width(stone.outline), 0.5 * 0.4 - 1e-12);
        }
    }
}

TEST(Ashlar, TheSameSeedLaysTheSameWallAndAnotherSeedAnotherOne) {
    AshlarMasonry ashlar = parseAshlarMasonry(kVariedCourses, "");
    WallFace wall{rectangle(0, 0, 6, 4), {rectangle(2, 1, 3, 3)}};
    Masonry a = layAshlar(ashlar, wall, {1, 5, 1}), b = layAshlar(ashlar, wall, {1, 5, 1});
    Masonry c = layAshlar(ashlar, wall, {1, 6, 1});
    ASSERT_EQ(a.stones.size(), b.stones.size());
    for (size_t i = 0; i < a.stones.size(); ++i) {
        EXPECT_EQ(a.stones[i].outline, b.stones[i].outline);
        EXPECT_EQ(a.stones[i].colour, b.stones[i].colour);
    }
    bool differs = a.stones.size() != c.stones.size();
    for (size_t i = 0; !differs && i < a.stones.size(); ++i) differs = !(a.stones[i].outline == c.stones[i].outline);
    EXPECT_TRUE(differs);
}

std::string errorOf(const std::string &text) {
    return inputErrorOf([&] { parseAshlarMasonry(text, "a.txt"); });
}

TEST(Ashlar, BadDescriptionsAreReportedWithTheirPlace) {
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,0.5,0.05; 0.4,0.5,0.1; 1,1,1; 2,2,2; 0.05; 3,3,3; }"),
              "a.txt:1:31: the maximum length 0.4 is below the minimum 0.5");
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,0.5,0.05; 1.5,0.5,0.1; 1,1,1; 2,2,2; 0.05; }"),
              "a.txt:1:1: AshlarMasonry takes 6 items (min size; max size; start colour; end colour; mortar "
              "thickness; mortar colour), found 5");
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,0.5,0.05; 1.5,0.5,0.1; 1,300,1; 2,2,2; 0.05; 3,3,3; }"),
              "a.txt:1:46: the stones' start colour: 300 is not a whole number from 0 to 255");
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,-0.5,0.05; 1.5,0.5,0.1; 1,1,1; 2,2,2; 0.05; 3,3,3; }"),
              "a.txt:1:21: the minimum stone size: the height is not positive");
    EXPECT_EQ(errorOf("Brick { 1,1,1; }"), "a.txt:1:1: expected one block, named 'AshlarMasonry', found 'Brick'");
    EXPECT_EQ(errorOf(""), "a.txt:1:1: the description has no block named 'AshlarMasonry'");
}

TEST(Ashlar, SizesAndMortarBeyondTheLimitAreReportedAtTheirField) {
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,0.5,0.05; 1.5,1e300,0.1; 1,1,1; 2,2,2; 0.05; 3,3,3; }"),
              "a.txt:1:35: the maximum stone size: the height 1e300 is above the 10000 units allowed");
    EXPECT_EQ(errorOf("AshlarMasonry { 0.5,0.5,0.05; 1.5,0.5,0.1; 1,1,1; 2,2,2; 1e5; 3,3,3; }"),
              "a.txt:1:58: the mortar thickness 1e5 is above the 10000 units allowed");
}

TEST(Ashlar, ScaledSizesThatDoNotSuitTheWallAreRefusedAtTheBlock) {
    AshlarMasonry ashlar = parseAshlarMasonry(kThesisExample, "a.txt");
    ashlar.mortarThickness = kMasonryLengthLimit;  // the mortar in metres overflowed to inf: an internal error
    EXPECT_EQ(inputErrorOf([&] {
                  layAshlar(ashlar, {rectangle(0, 0, 4, 3), {}}, {1e305, 0, 0});
              }),
              "a.txt:1:1: the masonry's sizes are not finite in metres");
    ashlar = parseAshlarMasonry(kThesisExample, "a.txt");
    EXPECT_EQ(inputErrorOf([&] {
                  layAshlar(ashlar, {rectangle(0, 0, 4, 3), {}}, {1e300, 0, 0});
              }),
              "a.txt:1:1: a size of 1.5e+300 m is out of all proportion to a wall of 4 × 3 m");
}

TEST(Ashlar, AWallThatWouldTakeTooManyStonesIsRefused) {
    AshlarMasonry ashlar = parseAshlarMasonry(kThesisExample, "a.txt");
    EXPECT_EQ(inputErrorOf([&] {
                  layAshlar(ashlar, {rectangle(0, 0, 1000, 1000), {}}, {0.001, 0, 0});
              }),
              "a.txt:1:1: the ashlar would lay more than 1048576 stones on a wall of 1000 × 1000 m");
}

}  // namespace
}  // namespace veduta
