// Quarters (quarters.h): a large district cut by main streets into pieces of about a kilometre
// that cover it but for the streets, each simple and counter-clockwise.
#include <gtest/gtest.h>

#include "slg/quarters.h"

namespace veduta {
namespace {

double totalArea(const std::vector<Polygon2d> &pieces) {
    double sum = 0;
    for (const Polygon2d &piece : pieces) sum += signedArea(piece);
    return sum;
}

TEST(Quarters, AnOutlineWithinOneCellStaysWhole) {
    Polygon2d outline{{0, 0}, {1200, 0}, {1200, 900}, {0, 900}};
    std::vector<Polygon2d> pieces = quarters(outline, 1000, 20);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_EQ(pieces[0], outline);
}

TEST(Quarters, ARectangleIsCutIntoCellsBetweenStreets) {
    // 3 × 2 cells of 1 km; two streets across and one along, each 20 m wide.
    Polygon2d outline{{0, 0}, {3000, 0}, {3000, 2000}, {0, 2000}};
    std::vector<Polygon2d> pieces = quarters(outline, 1000, 20);
    ASSERT_EQ(pieces.size(), 6u);
    double streets = 2 * 20 * 2000 + 20 * 3000 - 2 * 20 * 20;
    EXPECT_NEAR(totalArea(pieces), 3000 * 2000 - streets, 1e-3);
    for (const Polygon2d &piece : pieces) {
        EXPECT_GT(signedArea(piece), 0);
        EXPECT_TRUE(isSimple(piece));
        EXPECT_LE(signedArea(piece), 1000.0 * 1000.0);
    }
    // Row by row from the longest edge (the first of the outline's two 3 km edges).
    EXPECT_LT(vertexMean(pieces[0]).x, vertexMean(pieces[1]).x);
    EXPECT_LT(vertexMean(pieces[2]).y, vertexMean(pieces[3]).y);
}

TEST(Quarters, ATurnedLShapeIsCutAlongItsLongestEdge) {
    // An L of 4 × 3 km with a 2 × 1.5 km notch, turned by 30°.
    Polygon2d flat{{0, 0}, {4000, 0}, {4000, 1500}, {2000, 1500}, {2000, 3000}, {0, 3000}};
    double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    Polygon2d outline;
    for (Vec2d p : flat) outline.push_back({c * p.x - s * p.y + 500, s * p.x + c * p.y - 200});
    std::vector<Polygon2d> pieces = quarters(outline, 1000, 20);
    EXPECT_GT(pieces.size(), 6u);
    double whole = signedArea(outline);
    EXPECT_LT(totalArea(pieces), whole);
    EXPECT_GT(totalArea(pieces), 0.95 * whole) << "only the streets are taken";
    for (const Polygon2d &piece : pieces) {
        EXPECT_TRUE(isSimple(piece));
        for (Vec2d p : piece) EXPECT_LE(distanceOutside(outline, p), 1e-6) << "a rounding off at most";
    }
}

}  // namespace
}  // namespace veduta
