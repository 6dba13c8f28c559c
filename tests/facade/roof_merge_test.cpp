#include "facade/roof_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace veduta {
namespace {

const std::vector<Vec2d> kLarge{{0, 0}, {20, 0}, {20, 10}, {0, 10}};
const std::vector<Vec2d> kSmall{{8, 10}, {12, 10}, {12, 16}, {8, 16}};
const std::vector<bool> kLargeSeam{false, false, true, false};
const std::vector<bool> kSmallSeam{true, false, false, false};

// Fig 4.28: a large gable module, ridge along x at y = 5, 5 m high, and a small gable module
// docked on its long side y = 10, ridge along y touching the connection edge.
ModuleRoof largeGable() { return generalRoof(kLarge, 6, kLargeSeam, {3, 1, 0.5, 0.5, 0, 1, 5}); }
ModuleRoof smallGable(double height, double eavesZ = 6) {
    return generalRoof(kSmall, eavesZ, kSmallSeam, {0, 2, 0.5, 0.5, 0, 1, height});
}

bool insideOrOn(const std::vector<Vec2d> &outline, Vec2d p) {
    for (size_t i = 0; i < outline.size(); ++i) {
        if (cross(outline[(i + 1) % outline.size()] - outline[i], p - outline[i]) < -1e-12) return false;
    }
    return true;
}

size_t interfacesOn(const ModuleRoof &roof, size_t edge) {
    return std::count_if(roof.faces.begin(), roof.faces.end(), [&](const ModuleRoofFace &face) {
        return face.kind == RoofFaceKind::Interface && face.edge == edge;
    });
}

void expectPlanar(const ModuleRoof &roof) {
    for (const ModuleRoofFace &face : roof.faces) {
        Vec3d n = faceNormal(face);
        const Vec3d &o = face.corners[0];
        for (const Vec3d &c : face.corners) {
            EXPECT_NEAR(n.x * (c.x - o.x) + n.y * (c.y - o.y) + n.z * (c.z - o.z), 0, 1e-9);
        }
    }
}

// Every corner of the merged roof over the neighbour, and every edge between two such corners
// (a valley), lies in the neighbour's roof surface.
void expectSeamlessOn(const ModuleRoof &merged, const ModuleRoof &neighbour) {
    size_t checked = 0;
    for (const ModuleRoofFace &face : merged.faces) {
        for (size_t k = 0, n = face.corners.size(); k < n; ++k) {
            const Vec3d &a = face.corners[k], &b = face.corners[(k + 1) % n];
            Vec2d pa{a.x, a.y}, pb{b.x, b.y};
            if (!insideOrOn(neighbour.outline, pa)) continue;
            EXPECT_NEAR(a.z, *roofHeightAt(neighbour, pa), 1e-9) << a.x << " " << a.y;
            ++checked;
            if (!insideOrOn(neighbour.outline, pb)) continue;
            Vec2d mid = (pa + pb) * 0.5;
            EXPECT_NEAR((a.z + b.z) / 2, *roofHeightAt(neighbour, mid), 1e-9) << mid.x << " " << mid.y;
        }
    }
    EXPECT_GT(checked, 0u);
}

double coveredArea(const ModuleRoof &roof) {
    double area = 0;
    for (const ModuleRoofFace &face : roof.faces) {
        if (face.kind != RoofFaceKind::Slope) continue;
        for (size_t k = 0, n = face.corners.size(); k < n; ++k) {
            const Vec3d &a = face.corners[k], &b = face.corners[(k + 1) % n];
            area += (a.x * b.y - b.x * a.y) / 2;
        }
    }
    return area;
}

void expectSameFaces(const ModuleRoof &a, const ModuleRoof &b) {
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (size_t f = 0; f < a.faces.size(); ++f) {
        ASSERT_EQ(a.faces[f].corners.size(), b.faces[f].corners.size());
        for (size_t k = 0; k < a.faces[f].corners.size(); ++k) {
            EXPECT_EQ(a.faces[f].corners[k].x, b.faces[f].corners[k].x);
            EXPECT_EQ(a.faces[f].corners[k].y, b.faces[f].corners[k].y);
            EXPECT_EQ(a.faces[f].corners[k].z, b.faces[f].corners[k].z);
        }
    }
}

TEST(RoofMerge, TJunctionExtendsTheSmallRidgeOntoTheLargeRoof) {
    ModuleRoof large = largeGable(), small = smallGable(3);
    ASSERT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::Extended);
    // The small ridge at 9 m meets the large roof's north slope z = 16 − y at y = 7.
    EXPECT_NEAR(small.ridge->a.x, 10, 1e-12);
    EXPECT_NEAR(small.ridge->a.y, 7, 1e-12);
    EXPECT_EQ(small.ridge->a.z, 9);
    EXPECT_EQ(interfacesOn(small, 0), 0u) << "the interface at k is gone";
    EXPECT_EQ(interfacesOn(small, 2), 1u);
    expectSeamlessOn(small, large);
    expectPlanar(small);
    // The module's 24 m² plus the triangle (8, 10), (12, 10), (10, 7) beyond the seam.
    EXPECT_NEAR(coveredArea(small), 24 + 6, 1e-9);
    expectSameFaces(large, largeGable());
}

TEST(RoofMerge, EitherOrderExtendsTheSameRoof) {
    ModuleRoof large = largeGable(), small = smallGable(3), large2 = largeGable(), small2 = smallGable(3);
    ASSERT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::Extended);
    ASSERT_EQ(mergeRoofs(small2, 0, large2, 2), RoofMergeOutcome::Extended);
    expectSameFaces(small, small2);
}

// An oblique small ridge whose extension crosses the hip line of a hip roof before it reaches
// its height: one valley bends where it passes from the north slope onto the hip.
TEST(RoofMerge, ValleyBendsWhereItCrossesTheNeighboursHip) {
    ModuleRoof hip = generalRoof(kLarge, 6, kLargeSeam, {3, 1, 0.5, 0.5, 0.25, 0.75, 5});
    std::vector<Vec2d> slanted{{16, 10}, {20, 10}, {22, 14}, {18, 14}};
    ModuleRoof small = generalRoof(slanted, 6, kSmallSeam, {0, 2, 0.5, 0.5, 0, 1, 4.5});
    ASSERT_EQ(mergeRoofs(hip, 2, small, 0), RoofMergeOutcome::Extended);
    // Along (18, 10) − u (1, 2)/√5 the hip roof reaches 10.5 m at (15.5, 5), on its east hip.
    EXPECT_NEAR(small.ridge->a.x, 15.5, 1e-9);
    EXPECT_NEAR(small.ridge->a.y, 5, 1e-9);
    bool bends = std::any_of(small.faces.begin(), small.faces.end(), [](const ModuleRoofFace &face) {
        return std::any_of(face.corners.begin(), face.corners.end(), [](const Vec3d &c) {
            // The west slope's valley crosses the hip line y = x − 10 at (15 + 13/17, 5 + 13/17).
            return std::abs(c.x - (15 + 13.0 / 17)) < 1e-9 && std::abs(c.y - (5 + 13.0 / 17)) < 1e-9;
        });
    });
    EXPECT_TRUE(bends);
    EXPECT_EQ(interfacesOn(small, 0), 0u);
    expectSeamlessOn(small, hip);
    expectPlanar(small);
}

TEST(RoofMerge, RidgesThatBothTouchTheSeamStayAsTheyAre) {
    std::vector<Vec2d> west{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, east{{10, 0}, {20, 0}, {20, 10}, {10, 10}};
    ModuleRoof a = generalRoof(west, 6, {false, true, false, false}, {3, 1, 0.5, 0.5, 0, 1, 3});
    ModuleRoof b = generalRoof(east, 6, {false, false, false, true}, {3, 1, 0.5, 0.5, 0, 1, 3});
    EXPECT_EQ(mergeRoofs(a, 1, b, 3), RoofMergeOutcome::BothRidgesTouch);
    expectSameFaces(a, generalRoof(west, 6, {false, true, false, false}, {3, 1, 0.5, 0.5, 0, 1, 3}));
}

TEST(RoofMerge, RidgesThatNeitherTouchTheSeamStayAsTheyAre) {
    ModuleRoof large = largeGable();
    // The small ridge runs along the seam, 3 m from it.
    ModuleRoof small = generalRoof(kSmall, 6, kSmallSeam, {3, 1, 0.5, 0.5, 0, 1, 3});
    EXPECT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::NeitherRidgeTouches);
    expectSameFaces(small, generalRoof(kSmall, 6, kSmallSeam, {3, 1, 0.5, 0.5, 0, 1, 3}));
}

TEST(RoofMerge, RidgeAboveTheNeighboursRidgeStaysAsItIs) {
    ModuleRoof large = largeGable(), small = smallGable(6);
    EXPECT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::RidgeMissesNeighbour);
    expectSameFaces(small, smallGable(6));
    EXPECT_EQ(interfacesOn(small, 0), 1u);
}

TEST(RoofMerge, DifferentEavesHeightsAreNotMerged) {
    ModuleRoof large = largeGable(), small = smallGable(3, 7);
    EXPECT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::EavesDiffer);
}

TEST(RoofMerge, APyramidApexOnTheSeamIsNoGableEnd) {
    ModuleRoof large = largeGable();
    ModuleRoof small = generalRoof(kSmall, 6, kSmallSeam, {0, 2, 0.5, 0.5, 0, 0, 3});
    EXPECT_EQ(mergeRoofs(large, 2, small, 0), RoofMergeOutcome::NotAGableEnd);
}

}  // namespace
}  // namespace veduta
