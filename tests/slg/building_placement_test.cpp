// A lot's sidewalk and its building (digest-003 §2.2 step 4, §4.4): the strip along the front
// cut into quads, the band as deep as the shorter side, and the footprint in it after the
// Bauweise and the alignment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "slg/building_placement.h"
#include "slg/subdivision.h"

namespace veduta {
namespace {

// A lot on a street at y = 0, between two neighbours, with a gap behind.
PlanShape lot(double width, double depth) {
    return {{{0, 0}, {width, 0}, {width, depth}, {0, depth}},
            {EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap, EdgeLocation::NeighbourArea}};
}

PlanRandom random(uint32_t id) { return PlanRandom(11, id, RandomStream::SlgParameters); }

TEST(FrontStrip, ASidewalkIsAQuadAlongTheFrontAndTheLotGoesOnBehindIt) {
    PlanShape face = lot(10, 30);
    auto cut = cutFrontStrip(face, fourSides(face.points, 1), 2.5, EdgeLocation::Street);
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->quads, (std::vector<Polygon2d>{{{0, 0}, {10, 0}, {10, 2.5}, {0, 2.5}}}));
    ASSERT_TRUE(cut->behind);
    EXPECT_EQ(cut->behind->points, (Polygon2d{{0, 2.5}, {10, 2.5}, {10, 30}, {0, 30}}));
    EXPECT_EQ(cut->behind->locations, face.locations) << "the front behind the sidewalk faces the street";
    EXPECT_EQ(cut->strip.locations,
              (std::vector<EdgeLocation>{EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Street,
                                         EdgeLocation::NeighbourArea}));
    EXPECT_EQ(cut->behindSides.bottom, std::vector<size_t>{0});
    EXPECT_EQ(cut->behindSides.top, std::vector<size_t>{2});
}

TEST(FrontStrip, ACornerLotsSidewalkTurnsTheCornerInOneQuadPerFrontEdge) {
    // The front runs along two streets round the block's corner at (20, 0).
    PlanShape face{
        {{0, 0}, {20, 0}, {20, 15}, {0, 15}},
        {EdgeLocation::Street, EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::NeighbourArea}};
    FaceSides sides = fourSides(face.points, 2);
    auto cut = cutFrontStrip(face, sides, 3, EdgeLocation::Street);
    ASSERT_TRUE(cut);
    ASSERT_EQ(cut->quads.size(), 2u);
    EXPECT_EQ(cut->quads[0], (Polygon2d{{0, 0}, {20, 0}, {17, 3}, {0, 3}}));
    EXPECT_EQ(cut->quads[1], (Polygon2d{{20, 0}, {20, 15}, {17, 15}, {17, 3}}));
    double quads = 0;
    for (const Polygon2d &q : cut->quads) quads += signedArea(q);
    EXPECT_DOUBLE_EQ(quads, signedArea(cut->strip.points));
    EXPECT_DOUBLE_EQ(quads + signedArea(cut->behind->points), signedArea(face.points));
}

TEST(FrontStrip, AStripAsDeepAsTheFaceTakesItWhole) {
    PlanShape face = lot(10, 30);
    auto cut = cutFrontStrip(face, fourSides(face.points, 1), 30, EdgeLocation::Gap);
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->strip.points, face.points);
    EXPECT_FALSE(cut->behind);
}

TEST(FrontStrip, AFaceShallowerThanTheStripHasNone) {
    PlanShape face = lot(10, 2);
    EXPECT_FALSE(cutFrontStrip(face, fourSides(face.points, 1), 2.5, EdgeLocation::Street));
}

TEST(BuildingPlacement, AClosedBuildingStandsWallToWallAtTheFront) {
    PlanShape face = lot(12, 40);
    PlacementParameters p;
    p.buildingArea = 125;
    p.sideRatio = 1.2;
    auto placed = placeBuilding(face, fourSides(face.points, 1), p, random(1));
    ASSERT_TRUE(placed);
    double depth = std::sqrt(125 * 1.2);
    EXPECT_EQ(placed->bauweise, Bauweise::Closed);
    EXPECT_DOUBLE_EQ(placed->bandDepth, 40) << "as deep as the shorter side";
    ASSERT_EQ(placed->footprint.size(), 4u);
    EXPECT_NEAR(placed->footprint.points[2].y, depth, 1e-9);
    EXPECT_NEAR(placed->footprint.points[0].x, 0, 1e-12);
    EXPECT_NEAR(placed->footprint.points[1].x, 12, 1e-12);
    EXPECT_EQ(placed->footprint.locations,
              (std::vector<EdgeLocation>{EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap,
                                         EdgeLocation::NeighbourArea}));
}

TEST(BuildingPlacement, TheAlignmentPutsTheSpareDepthBehindAroundOrInFront) {
    PlanShape face = lot(12, 40);
    PlacementParameters p;
    p.buildingArea = 100;  // 10 m deep: 30 m to spare
    for (auto [alignment, front] :
         {std::pair{Alignment::Front, 0.0}, std::pair{Alignment::Middle, 15.0}, std::pair{Alignment::Back, 30.0}}) {
        p.alignment = alignment;
        auto placed = placeBuilding(face, fourSides(face.points, 1), p, random(2));
        ASSERT_TRUE(placed);
        EXPECT_NEAR(placed->footprint.points[0].y, front, 1e-9);
        EXPECT_NEAR(placed->footprint.points[3].y, front + 10, 1e-9);
        EXPECT_EQ(placed->footprint.locations[0], front == 0 ? EdgeLocation::Street : EdgeLocation::Gap);
    }
}

TEST(BuildingPlacement, AnOpenBuildingKeepsClearOfBothSidesAndSetsBackAFifthOfTheSpareDepth) {
    PlanShape face = lot(20, 40);
    PlacementParameters p;
    p.bauweise = Bauweise::Open;
    p.buildingArea = 100;
    for (uint32_t id = 0; id < 20; ++id) {
        auto placed = placeBuilding(face, fourSides(face.points, 1), p, random(id));
        ASSERT_TRUE(placed);
        EXPECT_EQ(placed->bauweise, Bauweise::Open);
        const Polygon2d &f = placed->footprint.points;
        EXPECT_NEAR(f[0].x, 5, 1e-9);
        EXPECT_NEAR(f[1].x, 15, 1e-9);
        EXPECT_GE(f[0].y, 0.1 * 30 - 1e-9);  // eq 56's x = rand(.1, .3) of the spare depth, front
        EXPECT_LE(f[0].y, 0.3 * 30 + 1e-9);
        EXPECT_NEAR(f[3].y - f[0].y, 10, 1e-9);
        for (EdgeLocation l : placed->footprint.locations) EXPECT_EQ(l, EdgeLocation::Gap);
    }
}

TEST(BuildingPlacement, AnOpenBuildingOnANarrowLotFallsBackToSemiOpenThenClosed) {
    PlacementParameters p;
    p.bauweise = Bauweise::Open;
    p.buildingArea = 100;
    PlanShape narrow = lot(8, 30);  // 8 − 2·3 < 3: not open; 8 − 3 ≥ 3: semi-open
    auto placed = placeBuilding(narrow, fourSides(narrow.points, 1), p, random(3));
    ASSERT_TRUE(placed);
    EXPECT_EQ(placed->bauweise, Bauweise::SemiOpen);
    EXPECT_NEAR(placed->footprint.points[1].x - placed->footprint.points[0].x, 5, 1e-9);
    int neighbours = int(std::ranges::count(placed->footprint.locations, EdgeLocation::NeighbourArea));
    EXPECT_EQ(neighbours, 1) << "on one side boundary";

    PlanShape narrower = lot(5, 30);
    placed = placeBuilding(narrower, fourSides(narrower.points, 1), p, random(3));
    ASSERT_TRUE(placed);
    EXPECT_EQ(placed->bauweise, Bauweise::Closed);
}

TEST(BuildingPlacement, ALotShallowerThanTheShortestSideHasNoBuilding) {
    PlanShape face = lot(12, 2.5);
    EXPECT_FALSE(placeBuilding(face, fourSides(face.points, 1), {}, random(4)));
}

TEST(BuildingPlacement, ASlantedBackMakesTheBandShallowerUntilItFits) {
    // The back falls from 20 m deep on the left to 8 m on the right: d = min(20, 8) = 8.
    PlanShape face{{{0, 0}, {12, 0}, {12, 8}, {0, 20}},
                   {EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap, EdgeLocation::NeighbourArea}};
    PlacementParameters p;
    p.buildingArea = 200;  // √200 = 14 m aimed, more than the band
    auto placed = placeBuilding(face, fourSides(face.points, 1), p, random(5));
    ASSERT_TRUE(placed);
    EXPECT_DOUBLE_EQ(placed->bandDepth, 8);
    for (Vec2d q : placed->footprint.points) EXPECT_NE(sideOf(face.points, q), Side::Outside);
}

TEST(BuildingPlacement, EveryLotOfABlockGetsAFootprintInsideIt) {
    Polygon2d outline = {{0, 0}, {90, 0}, {95, 70}, {-5, 65}};
    PlanParameters block;
    block.averageArea = 175;
    block.jitter = 0.05;
    for (uint32_t id = 0; id < 4; ++id) {
        Subdivision s = subdivide(outline, std::vector<EdgeLocation>(4, EdgeLocation::Street), block,
                                  PlanRandom(7, id, RandomStream::SlgPlan));
        int placedCount = 0;
        for (const PlanFace *face : s.borderFaces()) {
            PlanShape shape{s.graph.polygon(face->path), {}};
            for (SlgEdgeId e : face->path.edges) shape.locations.push_back(s.graph.edge(e).location);
            size_t front = std::ranges::find(face->path.nodes, face->right) - face->path.nodes.begin();
            auto sidewalk = cutFrontStrip(shape, fourSides(shape.points, front), 2.5, EdgeLocation::Street);
            ASSERT_TRUE(sidewalk && sidewalk->behind);
            for (Bauweise b : {Bauweise::Closed, Bauweise::SemiOpen, Bauweise::Open}) {
                PlacementParameters p;
                p.bauweise = b;
                p.buildingArea = 100;
                auto placed = placeBuilding(*sidewalk->behind, sidewalk->behindSides, p, random(id));
                if (!placed) continue;
                ++placedCount;
                EXPECT_TRUE(isSimple(placed->footprint.points));
                EXPECT_GT(signedArea(placed->footprint.points), 0);
                for (Vec2d q : placed->footprint.points) EXPECT_LT(distanceOutside(sidewalk->behind->points, q), 1e-9);
            }
        }
        EXPECT_GE(placedCount, int(s.borderFaces().size()) * 2) << id;
    }
}

}  // namespace
}  // namespace veduta
