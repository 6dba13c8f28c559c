// The futuristic city's floating streets (digest-002 §4, §10.2): crossings of 2n contour points
// and their centre, extruded into closed solids, and the slabs and boxes between them.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "city/floating_streets.h"
#include "scene/solid_checks.h"

namespace veduta {
namespace {

std::vector<CrossingArm> armsAt(std::initializer_list<float> degrees, float width = 7) {
    std::vector<CrossingArm> arms;
    for (float d : degrees) {
        float r = d * 3.14159265f / 180;
        arms.push_back({{std::cos(r), std::sin(r)}, width});
    }
    return arms;
}

// The distinct points of the crossing's top, and those on its rim (the ends of its side walls).
struct Top {
    std::set<std::pair<long, long>> points, rim;
};

Top topOf(const Mesh &crossing, float z) {
    Top top;
    auto key = [](const Vec3f &p) { return std::pair{std::lround(p.x * 1e4), std::lround(p.y * 1e4)}; };
    for (size_t t = 0; t < crossing.triangleCount(); ++t) {
        bool side = false, onTop = true;
        for (int i = 0; i < 3; ++i) {
            const Vec3f &p = crossing.positions[crossing.indices[3 * t + i]];
            onTop &= std::abs(p.z - z) < 1e-5f;
            side |= std::abs(crossing.normals[crossing.indices[3 * t + i]].z) < 0.5f;
        }
        for (int i = 0; i < 3; ++i) {
            const Vec3f &p = crossing.positions[crossing.indices[3 * t + i]];
            if (onTop) top.points.insert(key(p));
            if (side && std::abs(p.z - z) < 1e-5f) top.rim.insert(key(p));
        }
    }
    return top;
}

// Out from the centre by half the width times √2, as the futuristic levels place the mouths: the
// contour points of neighbouring arms at right angles are then distinct (an octagon).
constexpr float kMouth = 3.5f * 1.4142f;

TEST(CrossingSolid, NStreetsGiveTwoNContourPointsAroundTheCentre) {
    for (auto arms : {armsAt({0, 90, 180, 270}), armsAt({0, 120, 240}), armsAt({10, 100, 170, 215, 300})}) {
        Vec3f centre{5, -3, 40};
        Mesh crossing = crossingSolid(centre, arms, kMouth, 1);
        Top top = topOf(crossing, 40);
        EXPECT_EQ(top.points.size(), 2 * arms.size() + 1);
        EXPECT_EQ(top.rim.size(), 2 * arms.size());  // the contour, without the centre
        EXPECT_FALSE(top.rim.count({50000, -30000}));
        EXPECT_TRUE(isWatertight(crossing));
        EXPECT_GT(enclosedVolume(crossing), 0);
    }
}

TEST(CrossingSolid, IsAChamferedSquareAtAFourWayCrossing) {
    Mesh crossing = crossingSolid({0, 0, 0}, armsAt({0, 90, 180, 270}), kMouth, 1.5f);
    float corner = kMouth - 3.5f;  // the legs of each chamfer
    EXPECT_NEAR(enclosedVolume(crossing), (4 * kMouth * kMouth - 2 * corner * corner) * 1.5f, 1e-3);
    // With the mouths at half the width the arms share their corners: a square of 4 points.
    Mesh square = crossingSolid({0, 0, 0}, armsAt({0, 90, 180, 270}), 3.5f, 1);
    EXPECT_NEAR(enclosedVolume(square), 49, 1e-3);
    EXPECT_TRUE(isWatertight(square));
}

TEST(CrossingSolid, TwoStreetsAtATinyAngleStillTriangulate) {
    Mesh crossing = crossingSolid({0, 0, 0}, armsAt({0, 0.3f}), kMouth, 0.8f);
    EXPECT_TRUE(isWatertight(crossing));
    EXPECT_GT(enclosedVolume(crossing), 0);
    for (size_t t = 0; t < crossing.triangleCount(); ++t) {
        const Vec3f &a = crossing.positions[crossing.indices[3 * t]],
                    &b = crossing.positions[crossing.indices[3 * t + 1]],
                    &c = crossing.positions[crossing.indices[3 * t + 2]];
        EXPECT_GT(length(cross(b - a, c - a)), 0) << t;
    }
    // A dead end's single arm: the centre and its two contour points.
    Mesh end = crossingSolid({0, 0, 0}, armsAt({45}), kMouth, 1);
    EXPECT_TRUE(isWatertight(end));
    EXPECT_EQ(topOf(end, 0).points.size(), 3u);
}

TEST(SolidBox, IsClosedAndFacesOutForEitherHandedness) {
    Mesh right = solidBox({1, 2, 3}, {4, 0, 0}, {0, 5, 0}, {0, 0, 6});
    Mesh left = solidBox({1, 2, 3}, {0, 5, 0}, {4, 0, 0}, {0, 0, 6});
    for (const Mesh *box : {&right, &left}) {
        EXPECT_TRUE(isWatertight(*box));
        EXPECT_NEAR(enclosedVolume(*box), 120, 1e-3);
    }
}

TEST(StreetSlab, SlopesBetweenItsEndsAndKeepsItsWidth) {
    Mesh slab = streetSlab({0, 0, 40}, {30, 0, 42}, 7, 1);
    EXPECT_TRUE(isWatertight(slab));
    EXPECT_NEAR(enclosedVolume(slab), 30 * 7 * 1, 1e-2);  // a sheared box keeps its volume
    float lo = 1e9f, hi = -1e9f;
    for (const Vec3f &p : slab.positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    EXPECT_NEAR(hi - lo, 7, 1e-5);
}

}  // namespace
}  // namespace veduta
