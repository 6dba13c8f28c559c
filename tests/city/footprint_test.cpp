#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "city/footprint.h"
#include "input_error.h"

namespace veduta {
namespace {

const FileLoc kLoc{"city.xml", 4, 7};

// The message of the InputError normaliseFootprint throws, or "no error".
std::string inputError(Footprint footprint) {
    return test::inputErrorOf([&] { normaliseFootprint(footprint, kLoc); });
}

bool samePoint(Vec2f a, Vec2f b) { return a.x == b.x && a.y == b.y; }

TEST(Footprint, CounterClockwiseIsKept) {
    Footprint f{{{0, 0}, {20, 0}, {20, 12}, {0, 12}}, {true, false, false, false}, 0};
    Footprint before = f;
    EXPECT_FALSE(normaliseFootprint(f, kLoc));
    ASSERT_EQ(f.points.size(), 4u);
    for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(samePoint(f.points[i], before.points[i]));
    EXPECT_EQ(f.streetEdges, before.streetEdges);
}

TEST(Footprint, ClockwiseIsReversedAndStreetFlagsFollowTheirEdges) {
    // Clockwise; the street runs along the east side, (20, 12) → (20, 0), edge 2.
    Footprint f{{{0, 0}, {0, 12}, {20, 12}, {20, 0}}, {false, false, true, false}, 0};
    std::optional<std::string> warning = normaliseFootprint(f, kLoc);
    ASSERT_TRUE(warning);
    EXPECT_NE(warning->find("city.xml:4:7: "), std::string::npos) << *warning;
    EXPECT_NE(warning->find("clockwise"), std::string::npos) << *warning;
    EXPECT_TRUE(isCounterClockwise(f.points));
    ASSERT_EQ(f.streetEdges.size(), 4u);
    for (size_t e = 0; e < 4; ++e) {
        bool east = samePoint(f.edgeStart(e), {20, 0}) && samePoint(f.edgeEnd(e), {20, 12});
        EXPECT_EQ(f.streetEdges[e], east) << "edge " << e;
    }
}

TEST(Footprint, NoStreetFlagsMeansNoStreetEdges) {
    Footprint f{{{0, 0}, {20, 0}, {0, 12}}, {}, 0};
    normaliseFootprint(f, kLoc);
    EXPECT_EQ(f.streetEdges, std::vector<bool>(3, false));
}

TEST(Footprint, InvalidOutlinesAreInputErrorsAtTheirPlace) {
    EXPECT_NE(inputError({{{0, 0}, {1, 0}}, {}, 0}).find("city.xml:4:7: a footprint needs at least 3 points"),
              std::string::npos);
    // A bow tie: edges 0 and 2 cross.
    EXPECT_NE(inputError({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, {}, 0}).find("crosses"), std::string::npos);
    // A spike: edge 1 runs back along edge 0.
    EXPECT_NE(inputError({{{0, 0}, {10, 0}, {5, 0}, {5, 5}}, {}, 0}).find("crosses"), std::string::npos);
    // Collinear points enclose nothing.
    EXPECT_NE(inputError({{{0, 0}, {5, 0}, {10, 0}}, {}, 0}).find("crosses"), std::string::npos);
    EXPECT_NE(inputError({{{0, 0}, {10, 0}, {10, 10}, {0, 0}, {0, 10}}, {}, 0}).find("point 4 repeats point 1"),
              std::string::npos);
    EXPECT_NE(inputError({{{0, 0}, {10, 0}, {10, 10}}, {true, false}, 0}).find("3 edges has 2 street flags"),
              std::string::npos);
    EXPECT_NE(inputError({{{0, 0}, {10, 0}, {NAN, 10}}, {}, 0}).find("point 3 is not a finite number"),
              std::string::npos);
}

// Outlines of many points: repeats are found without comparing every pair, the first repeat
// in reading order is the one named, and an outline beyond kMaxOutlinePoints stops at once.
TEST(Footprint, LargeOutlinesAreCheckedInTimeAndStopAtTheirLimit) {
    auto circle = [](size_t n) {
        Footprint f;
        for (size_t i = 0; i < n; ++i) {
            double a = 2 * M_PI * double(i) / double(n);
            f.points.push_back({float(1000 * std::cos(a)), float(1000 * std::sin(a))});
        }
        return f;
    };
    Footprint many = circle(kMaxOutlinePoints);
    EXPECT_EQ(inputError(many), "no error");
    Footprint repeats = circle(1000);
    repeats.points[700] = repeats.points[3];
    repeats.points[500] = repeats.points[9];
    EXPECT_NE(inputError(repeats).find("point 501 repeats point 10"), std::string::npos) << inputError(repeats);
    EXPECT_EQ(inputError(circle(100000)),
              "city.xml:4:7: an outline of 100000 points is more than veduta takes (20000)");
}

TEST(Footprint, TriangulationCoversAnLShapeWithNMinusTwoCounterClockwiseTriangles) {
    std::vector<Vec2f> l{{0, 0}, {24, 0}, {24, 12}, {12, 12}, {12, 24}, {0, 24}};
    std::vector<uint32_t> indices = triangulatePolygon(l);
    ASSERT_EQ(indices.size(), 3u * 4);
    double area = 0;
    for (size_t t = 0; t < indices.size(); t += 3) {
        Vec2f a = l[indices[t]], b = l[indices[t + 1]], c = l[indices[t + 2]];
        double twice = double(b.x - a.x) * (c.y - a.y) - double(c.x - a.x) * (b.y - a.y);
        EXPECT_GT(twice, 0) << "triangle " << t / 3;
        area += twice / 2;
    }
    EXPECT_DOUBLE_EQ(area, 24.0 * 12 + 12.0 * 12);
}

TEST(Footprint, LiesInsideNeedsEveryPointInsideAndNoCrossing) {
    std::vector<Vec2f> l{{0, 0}, {24, 0}, {24, 12}, {12, 12}, {12, 24}, {0, 24}};
    EXPECT_TRUE(liesInside(std::vector<Vec2f>{{2, 2}, {22, 2}, {22, 10}, {10, 10}, {10, 22}, {2, 22}}, l));
    // All corners inside the L, but the edge from (20, 10) to (10, 20) cuts across its notch.
    EXPECT_FALSE(liesInside(std::vector<Vec2f>{{2, 2}, {20, 2}, {20, 10}, {10, 20}, {2, 20}}, l));
    // Touching the outline is not inside.
    EXPECT_FALSE(liesInside(std::vector<Vec2f>{{0, 0}, {10, 2}, {2, 10}}, l));
}

}  // namespace
}  // namespace veduta
