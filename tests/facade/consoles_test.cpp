#include "facade/consoles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "thesis_figures.h"

namespace veduta {
namespace {

using thesis::kFigure5_28;

struct Placed {
    CorniceDescription cornice;
    double scale = 0;
    ProfileOutline outline;
};

Placed figure5_28(double height) {
    Placed placed;
    placed.cornice = parseCorniceDescription(kFigure5_28, "cornice.txt");
    ProfileOutline traced = traceProfile(placed.cornice.profile, 5);
    placed.scale = heightScale(placed.cornice.profile, traced, height);
    placed.outline = scaledOutline(traced, placed.scale);
    return placed;
}

TEST(Consoles, TenMetreRunWithAbstand1_5GetsSevenEvenlySpaced) {
    Placed placed = figure5_28(0.5);
    SweepPath path{{{0, 0}, {10, 0}}, 3.0};
    std::vector<Transform> consoles = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale);
    ASSERT_EQ(consoles.size(), 7u);
    for (size_t i = 0; i < consoles.size(); ++i) {
        Vec3f foot = consoles[i].applyPoint({0, 0, 0});
        EXPECT_NEAR(foot.x, 0.5 + 1.5 * double(i), 1e-5);  // centred: 0.5 m free at both ends
        EXPECT_NEAR(foot.y, 0, 1e-6);
        EXPECT_NEAR(foot.z, 3.0, 1e-6);
    }
}

TEST(Consoles, UnitBoxFillsTheScaledRectangleAndTheProfilesReach) {
    Placed placed = figure5_28(0.5);
    double reach = 0;
    for (Vec2d point : placed.outline.points) reach = std::max(reach, point.x);
    SweepPath path{{{0, 0}, {10, 0}}, 3.0};  // outside on the right: -y
    Transform console = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale)[0];
    Vec3f corner = console.applyPoint({0.5f, 1, 1});
    EXPECT_NEAR(corner.x, 0.5 + 0.35 * placed.scale / 2, 1e-6);
    EXPECT_NEAR(corner.y, -reach, 1e-6);
    EXPECT_NEAR(corner.z, 3.0 + 0.45 * placed.scale, 1e-6);
    EXPECT_GT(console.determinant(), 0);  // not mirrored
}

TEST(Consoles, RunWithItsOutsideOnTheLeftIsNotMirrored) {
    Placed placed = figure5_28(0.5);
    SweepPath path{{{0, 0}, {10, 0}}, 0, false, OutwardSide::Left};
    std::vector<Transform> consoles = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale);
    ASSERT_EQ(consoles.size(), 7u);
    for (const Transform &console : consoles) {
        EXPECT_GT(console.determinant(), 0);
        EXPECT_GT(console.applyPoint({0, 0, 1}).y, 0);  // out of the wall is +y here
    }
}

TEST(Consoles, ConcaveCornerKeepsConsolesClearOfTheMitre) {
    Placed placed = figure5_28(0.5);
    double reach = 0;
    for (Vec2d point : placed.outline.points) reach = std::max(reach, point.x);
    double halfWidth = 0.35 * placed.scale / 2;
    // An L, counter-clockwise: the concave corner is (4, 4).
    SweepPath path{{{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}}, 0, true};
    std::vector<Transform> consoles = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale);
    EXPECT_FALSE(consoles.empty());
    for (const Transform &console : consoles) {
        Vec3f foot = console.applyPoint({0, 0, 0});
        double toCorner = std::hypot(foot.x - 4, foot.y - 4);
        EXPECT_GE(toCorner, halfWidth - 1e-6);
        if (std::abs(foot.x - 4) < 1e-6 || std::abs(foot.y - 4) < 1e-6) {
            EXPECT_GE(toCorner, halfWidth + reach - 1e-5);
        }
    }
}

double reachOf(const ProfileOutline &outline) {
    double reach = 0;
    for (Vec2d point : outline.points) reach = std::max(reach, point.x);
    return reach;
}

// Edges just long enough for one more console than fits with a margin for the mitre: the old
// margin, taken at the wrong end, let the last console of the wall that ends at the concave
// corner run across the mitre plane into the next wall's.
TEST(Consoles, NoConsoleCrossesTheMitrePlaneAtAConcaveCorner) {
    Placed placed = figure5_28(0.5);
    double halfWidth = 0.35 * placed.scale / 2, depth = reachOf(placed.outline);
    ASSERT_GT(depth, 0.02);
    double edge = 2 * halfWidth + 3 + 0.01;  // two spacings and 1 cm over, without the margin
    double c = 8 - edge;                     // the concave corner is (c, 4)
    SweepPath path{{{0, 0}, {8, 0}, {8, 4}, {c, 4}, {c, 4 + edge}, {0, 4 + edge}}, 0, true};
    std::vector<Transform> consoles = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale);
    size_t before = 0, after = 0;  // on the wall ending at the corner, and on the one starting there
    for (const Transform &console : consoles) {
        Vec3f foot = console.applyPoint({0, 0, 0});
        bool ending = std::abs(foot.y - 4) < 1e-5 && foot.x > c, starting = std::abs(foot.x - c) < 1e-5 && foot.y > 4;
        if (!ending && !starting) continue;
        ++(ending ? before : after);
        // The mitre plane is the diagonal through the corner; the first wall's consoles stay on
        // its side (x - c >= y - 4), the second wall's on the other.
        for (float side : {-0.5f, 0.5f})
            for (float out : {0.0f, 1.0f}) {
                Vec3f corner = console.applyPoint({side, 0, out});
                double beyond = (corner.y - 4) - (corner.x - c);
                EXPECT_LE(ending ? beyond : -beyond, 1e-5) << "console at " << foot.x << ", " << foot.y;
            }
    }
    EXPECT_EQ(before, 2u);
    EXPECT_EQ(after, 2u);
}

// At a convex corner the mitre lies beyond the edge: the consoles keep only half their width
// from the corner (they were once pulled back by their depth at an edge's end, losing one).
TEST(Consoles, ConvexCornerTakesNoMarginForTheMitre) {
    Placed placed = figure5_28(0.5);
    double halfWidth = 0.35 * placed.scale / 2, depth = reachOf(placed.outline);
    ASSERT_GT(depth, 0.02);
    double side = 2 * halfWidth + 6 + 0.01;  // four spacings and 1 cm over
    SweepPath path{{{0, 0}, {side, 0}, {side, side}, {0, side}}, 0, true};
    std::vector<Transform> consoles = placeConsoles(path, placed.cornice.consoles[0], placed.outline, placed.scale);
    EXPECT_EQ(consoles.size(), 4u * 5);
    for (const Transform &console : consoles) {
        for (float x : {-0.5f, 0.5f}) {
            Vec3f corner = console.applyPoint({x, 0, 0});
            EXPECT_GE(std::min({corner.x, corner.y, float(side) - corner.x, float(side) - corner.y}), -1e-5f);
        }
    }
}

TEST(Consoles, CountIsLimited) {
    Placed placed = figure5_28(0.5);
    Console console = placed.cornice.consoles[0];
    console.spacing = 1e-5;
    try {
        placeConsoles(SweepPath{{{0, 0}, {10, 0}}}, console, placed.outline, placed.scale);
        FAIL() << "no error";
    } catch (const InputError &error) {
        EXPECT_EQ(std::string(error.what()),
                  "cornice.txt:2:12: consoles 1e-05 m apart would be more than 100000 on a 10 m wall");
    }
}

}  // namespace
}  // namespace veduta
