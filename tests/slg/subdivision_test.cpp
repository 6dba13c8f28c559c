// One level of the SLG subdivision (digest-003 §2.2, §2.6) and its invariants (§8.2): faces
// counter-clockwise, disjoint, covering the outline, each border face with two landmarks.
#include <gtest/gtest.h>

#include <cmath>

#include "slg/subdivision.h"
#include "slg/thesis_levels.h"

namespace veduta {
namespace {

std::vector<EdgeLocation> streets(size_t n) { return std::vector<EdgeLocation>(n, EdgeLocation::Street); }

double totalArea(const std::vector<Polygon2d> &polygons) {
    double sum = 0;
    for (const Polygon2d &p : polygons) sum += signedArea(p);
    return sum;
}

// The invariants of §8.2 for any subdivision.
void expectSound(const Subdivision &s, const Polygon2d &outline) {
    std::vector<Polygon2d> polygons = facePolygons(s);
    for (size_t i = 0; i < polygons.size(); ++i) {
        EXPECT_TRUE(isSimple(polygons[i])) << "face " << i;
        EXPECT_GT(signedArea(polygons[i]), 0) << "face " << i;
        // Landmarks on a slanted edge are a rounding off it.
        for (Vec2d p : polygons[i]) EXPECT_LT(distanceOutside(outline, p), 1e-12 * 100) << "face " << i;
        // No vertex of another face strictly inside this one, and the areas add up: disjoint.
        for (size_t j = 0; j < polygons.size(); ++j) {
            if (j == i) continue;
            for (Vec2d p : polygons[j])
                EXPECT_NE(sideOf(polygons[i], p), Side::Inside) << "face " << j << " in face " << i;
        }
    }
    EXPECT_NEAR(totalArea(polygons), signedArea(outline), 1e-6 * signedArea(outline));
    for (const PlanFace *face : s.borderFaces()) {
        int landmarks = 0;
        for (SlgNodeId n : face->path.nodes) landmarks += s.graph.node(n).type == SlgNodeType::Landmark ? 1 : 0;
        EXPECT_EQ(landmarks, 2);
        EXPECT_EQ(face->path.nodes.front(), face->left);
    }
}

TEST(Subdivision, FourRoomsOfATwelveBySixApartment) {
    Polygon2d outline = {{0, 0}, {12, 0}, {12, 6}, {0, 6}};
    PlanParameters p = apartmentLevel();
    p.count = 4;
    p.jitter = 0;
    Subdivision s = subdivide(outline, streets(4), p, PlanRandom(1, 1, RandomStream::SlgPlan));
    expectSound(s, outline);
    EXPECT_EQ(s.deletedFaces, 0);
    ASSERT_EQ(s.faces.size(), 4u);
    std::vector<double> areas;
    for (const Polygon2d &polygon : facePolygons(s)) areas.push_back(signedArea(polygon));
    // The rays from (4,0), (8,0), (12,3) and (6,6) cross at (4,3), (6,3) and (8,3).
    EXPECT_EQ(areas, (std::vector<double>{12, 12, 18, 30}));
}

TEST(Subdivision, OneLandmarkLeavesTheOutlineTheOnlyFace) {
    Polygon2d outline = {{0, 0}, {5, 0}, {5, 4}, {0, 4}};
    PlanParameters p = apartmentLevel();
    p.count = 1;
    Subdivision s = subdivide(outline, streets(4), p, PlanRandom(1, 1, RandomStream::SlgPlan));
    ASSERT_EQ(s.faces.size(), 1u);
    EXPECT_FALSE(s.faces[0].isBorder());
    EXPECT_EQ(facePolygons(s)[0], outline);
}

TEST(Subdivision, ABlockGetsLotsRoundACourtyard) {
    Polygon2d outline = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    for (uint32_t id = 0; id < 5; ++id) {
        Subdivision s = subdivide(outline, streets(4), blockLevel(150), PlanRandom(3, id, RandomStream::SlgPlan));
        EXPECT_EQ(s.landmarks.size(), 28u);
        expectSound(s, outline);
        EXPECT_GT(s.borderFaces().size(), 20u) << id;
        EXPECT_LT(s.borderFaces().size(), s.faces.size()) << "the courtyard is an inner face";
        for (const PlanFace *face : s.borderFaces())
            for (double run : straightRuns(s.graph.polygon(face->path))) EXPECT_GE(run, 8.66 - 1e-6);
    }
}

TEST(Subdivision, AnLShapedBlockIsSoundForManySeeds) {
    Polygon2d outline = {{0, 0}, {80, 0}, {80, 40}, {40, 40}, {40, 80}, {0, 80}};
    for (uint32_t id = 0; id < 10; ++id) {
        Subdivision s = subdivide(outline, streets(6), blockLevel(200), PlanRandom(5, id, RandomStream::SlgPlan));
        expectSound(s, outline);
        EXPECT_GT(s.borderFaces().size(), 10u) << id;
    }
}

TEST(Subdivision, TwoLandmarksOnOppositeSidesAreJoinedByAChord) {
    // A 12 × 10 storey (Table 13) gets its two landmarks on the long sides; their rays cross
    // nothing.
    Polygon2d outline = {{0, 0}, {12, 0}, {12, 10}, {0, 10}};
    PlanParameters p = storeyLevel();
    EXPECT_EQ(landmarkCount(p, 120, 44, 4), 2);
    for (uint32_t id = 0; id < 10; ++id) {
        Subdivision s = subdivide(outline, streets(4), p, PlanRandom(2, id, RandomStream::SlgPlan));
        expectSound(s, outline);
        EXPECT_EQ(s.deletedFaces, 0) << id;
        ASSERT_EQ(s.faces.size(), 2u) << id;
        for (const Polygon2d &face : facePolygons(s)) EXPECT_NEAR(signedArea(face), 60, 60 * 0.05) << id;
    }
}

TEST(Subdivision, SkewedBlocksKeepTheirFaces) {
    // Rays off the axes cross at points that lie on their lines only to a rounding; a face that
    // runs straight on through them is one run, not a chain of 10⁻¹⁵ turns the search refuses.
    for (const Polygon2d &outline :
         {Polygon2d{{0, 0}, {100, 0}, {104, 80}, {-3, 78}}, Polygon2d{{0, 0}, {90, 0}, {95, 70}, {-5, 65}}}) {
        for (uint32_t id = 0; id < 3; ++id) {
            Subdivision s = subdivide(outline, streets(4), blockLevel(175), PlanRandom(7, id, RandomStream::SlgPlan));
            expectSound(s, outline);
            EXPECT_EQ(s.deletedFaces, 0) << id;
            EXPECT_EQ(s.borderFaces().size(), s.landmarks.size()) << id;
        }
    }
}

TEST(Subdivision, TheSameSeedGivesTheSamePlan) {
    Polygon2d outline = {{0, 0}, {60, 0}, {70, 50}, {-5, 45}};
    auto plan = [&] {
        return facePolygons(subdivide(outline, streets(4), blockLevel(175), PlanRandom(9, 4, RandomStream::SlgPlan)));
    };
    EXPECT_EQ(plan(), plan());
}

}  // namespace
}  // namespace veduta
