// The locations each level gives the edges of its plan (digest-003 §2.2 step 7).
#include <gtest/gtest.h>

#include "slg/plan_level.h"
#include "slg/thesis_levels.h"

namespace veduta {
namespace {

std::vector<EdgeLocation> streets(size_t n) { return std::vector<EdgeLocation>(n, EdgeLocation::Street); }

TEST(PlanLevel, ABlocksLotsShareNeighbourAreasAndFaceTheCourtyardOverAGap) {
    Polygon2d outline = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    Subdivision s = subdivide(outline, streets(4), blockLevel(150), PlanRandom(3, 1, RandomStream::SlgPlan));
    labelEdges(s, PlanLevel::Block);
    std::vector<int> uses(s.graph.edges().size(), 0);
    for (const PlanFace *face : s.borderFaces())
        for (SlgEdgeId e : face->path.edges) ++uses[e];
    int neighbours = 0, gaps = 0;
    for (SlgEdgeId e = 0; e < s.graph.edges().size(); ++e) {
        const SlgEdge &edge = s.graph.edge(e);
        if (edge.removed) continue;
        if (edge.outer) {
            EXPECT_EQ(edge.location, EdgeLocation::Street);
            continue;
        }
        EXPECT_EQ(edge.location, uses[e] == 2 ? EdgeLocation::NeighbourArea : EdgeLocation::Gap);
        (uses[e] == 2 ? neighbours : gaps) += 1;
    }
    EXPECT_GT(neighbours, 20);
    EXPECT_GT(gaps, 4) << "the lots' backs on the courtyard";
}

TEST(PlanLevel, CitiesAndDistrictsAreCutByStreetsAlone) {
    Polygon2d outline = {{0, 0}, {1200, 0}, {1200, 900}, {0, 900}};
    PlanParameters district = blockLevel(5000);  // Table 6's face area
    std::vector<EdgeLocation> parent(4, EdgeLocation::Gap);
    Subdivision s = subdivide(outline, parent, district, PlanRandom(1, 1, RandomStream::SlgPlan));
    labelEdges(s, PlanLevel::District);
    for (const SlgEdge &edge : s.graph.edges())
        if (!edge.removed) {
            EXPECT_EQ(edge.location, EdgeLocation::Street);
        }
}

TEST(PlanLevel, AStoreysApartmentsShareWallsAndKeepTheShellsLocations) {
    Polygon2d outline = {{0, 0}, {16, 0}, {16, 12}, {0, 12}};
    std::vector<EdgeLocation> shell = {EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap,
                                       EdgeLocation::NeighbourArea};
    PlanParameters p = storeyLevel();
    p.count = 4;
    p.jitter = 0;
    Subdivision s = subdivide(outline, shell, p, PlanRandom(1, 1, RandomStream::SlgPlan));
    labelEdges(s, PlanLevel::Building);
    for (const SlgEdge &edge : s.graph.edges()) {
        if (edge.removed) continue;
        if (edge.outer) {
            Vec2d a = s.graph.position(edge.start);
            EdgeLocation expected =
                a.y == 0 && s.graph.position(edge.end).y == 0 ? EdgeLocation::Street : edge.location;
            EXPECT_EQ(edge.location, expected);
            EXPECT_FALSE(edge.location == EdgeLocation::NeighbourApartment);
        } else {
            EXPECT_TRUE(edge.location == EdgeLocation::NeighbourApartment ||
                        edge.location == EdgeLocation::HouseCorridor);
        }
    }
}

}  // namespace
}  // namespace veduta
