// The corridors of Listing 3 (digest-003 §2.2 step 4): a house corridor from the entrance that
// reaches every apartment of a storey, and an apartment corridor of the entrance's rooms and
// the rooms' tops.
#include <gtest/gtest.h>

#include <algorithm>

#include "slg/corridors.h"
#include "slg/thesis_levels.h"

namespace veduta {
namespace {

std::vector<EdgeLocation> streets(size_t n) { return std::vector<EdgeLocation>(n, EdgeLocation::Street); }

// The landmark on the edge from (0, 0) nearest the middle of the front.
SlgNodeId frontLandmark(const Subdivision &s) {
    SlgNodeId best = kNoSlgId;
    double mid = (s.outline[0].x + s.outline[1].x) / 2;
    for (SlgNodeId l : s.landmarks) {
        Vec2d p = s.graph.position(l);
        if (p.y == 0 && (best == kNoSlgId || std::abs(p.x - mid) < std::abs(s.graph.position(best).x - mid))) best = l;
    }
    return best;
}

double corridorArea(const CorridorPlan &plan, const Polygon2d &outline) {
    double area = 0;
    for (const std::vector<Polygon2d> &piece : corridorPieces(outline, plan.faces))
        for (const Polygon2d &ring : piece) area += signedArea(ring);
    return area;
}

void expectReachesEveryFace(const CorridorPlan &plan, const Polygon2d &outline, double entranceWidth) {
    double faces = 0;
    for (size_t f = 0; f < plan.faces.size(); ++f) {
        const Polygon2d &face = plan.faces[f].points;
        EXPECT_TRUE(isSimple(face));
        faces += signedArea(face);
        std::vector<double> free = freeLengths(plan.faces, f, outline);
        EXPECT_GE(*std::ranges::max_element(free), entranceWidth) << "face " << f;
    }
    EXPECT_EQ(plan.unreached, 0);
    ASSERT_EQ(corridorPieces(outline, plan.faces).size(), 1u) << "one corridor";
    EXPECT_NEAR(corridorArea(plan, outline) + faces, signedArea(outline), 1e-6);
}

TEST(Corridor, TwoApartmentsShareACorridorFromTheDoorAlongTheirWall) {
    Polygon2d outline = {{0, 0}, {12, 0}, {12, 10}, {0, 10}};
    for (uint32_t id = 0; id < 8; ++id) {
        Subdivision s = subdivide(outline, streets(4), storeyLevel(), PlanRandom(4, id, RandomStream::SlgPlan));
        ASSERT_EQ(s.borderFaces().size(), 2u) << id;
        CorridorPlan plan = makeCorridor(s, frontLandmark(s), {});
        expectReachesEveryFace(plan, outline, 1.0);
        // The corridor runs from the front to the back: 1.5 m wide, 10 m long.
        EXPECT_NEAR(corridorArea(plan, outline), 15, 0.1) << id;
        for (const PlanShape &face : plan.faces)
            EXPECT_EQ(std::ranges::count(face.locations, EdgeLocation::HouseCorridor), 1) << id;
    }
}

TEST(Corridor, FourApartmentsAreAllReachedFromTheEntrance) {
    Polygon2d outline = {{0, 0}, {20, 0}, {20, 14}, {0, 14}};
    PlanParameters p = storeyLevel();
    p.count = 4;
    for (uint32_t id = 0; id < 8; ++id) {
        Subdivision s = subdivide(outline, streets(4), p, PlanRandom(5, id, RandomStream::SlgPlan));
        if (s.deletedFaces > 0) continue;
        CorridorPlan plan = makeCorridor(s, frontLandmark(s), {});
        EXPECT_EQ(plan.tooSmall, 0) << id;
        expectReachesEveryFace(plan, outline, 1.0);
    }
}

TEST(Corridor, AnApartmentCorridorMovesOnlyTheTopsBesideTheEntranceRooms) {
    Polygon2d outline = {{0, 0}, {14, 0}, {14, 9}, {0, 9}};
    PlanParameters p = apartmentLevel();
    p.jitter = 0;
    Subdivision s = subdivide(outline, streets(4), p, PlanRandom(6, 1, RandomStream::SlgPlan));
    ASSERT_GE(s.borderFaces().size(), 3u);
    CorridorParameters corridor;
    corridor.kind = CorridorKind::Apartment;
    CorridorPlan plan = makeCorridor(s, frontLandmark(s), corridor);
    ASSERT_EQ(plan.faces.size(), s.borderFaces().size());
    for (size_t f = 0; f < plan.faces.size(); ++f) {
        const PlanFace &face = *s.borderFaces()[f];
        bool entrance = face.left == frontLandmark(s) || face.right == frontLandmark(s);
        bool moved = signedArea(plan.faces[f].points) < signedArea(s.graph.polygon(face.path)) - 1e-9;
        EXPECT_EQ(moved, entrance || !fourSides(s.graph.polygon(face.path), frontEdges(face)).top.empty()) << f;
        for (EdgeLocation l : plan.faces[f].locations) EXPECT_NE(l, EdgeLocation::HouseCorridor);
    }
    EXPECT_EQ(plan.unreached, 0) << "apartment corridors do not count unreached rooms";
}

TEST(FreeLengths, EdgesOnTheOutlineOrAnotherFaceAreNotFree) {
    Polygon2d outline = {{0, 0}, {10, 0}, {10, 4}, {0, 4}};
    std::vector<PlanShape> faces = {
        {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, streets(4)},
        {{{6, 0}, {10, 0}, {10, 4}, {6, 4}}, streets(4)},
        {{{4, 0}, {6, 0}, {6, 2}, {4, 2}}, streets(4)},
    };
    // Face 0's right edge: 2 m against face 2, 2 m free.
    EXPECT_EQ(freeLengths(faces, 0, outline), (std::vector<double>{0, 2, 0, 0}));
    EXPECT_EQ(freeLengths(faces, 2, outline), (std::vector<double>{0, 0, 2, 0}));
}

}  // namespace
}  // namespace veduta
