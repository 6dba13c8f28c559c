#include "facade/module_partition.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "facade/plan_features.h"

namespace veduta {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

const FloorPlanModule kPrototype{{}, "Haus", 0.36, 2.8, "Putz", {}};

Polygon toPolygon(const std::vector<Vec2d> &ring) {
    Polygon polygon;
    for (Vec2d p : ring) polygon.push_back(Kernel::Point_2(p.x, p.y));
    return polygon;
}

// The union of the modules (exact) is one polygon without holes.
Polygon unionOf(const FloorPlan &plan) {
    std::vector<Polygon> modules;
    for (const FloorPlanModule &m : plan.modules()) modules.push_back(toPolygon(m.outline));
    std::vector<PolygonWithHoles> joined;
    CGAL::join(modules.begin(), modules.end(), std::back_inserter(joined));
    EXPECT_EQ(joined.size(), 1u);
    EXPECT_FALSE(joined.empty() || joined[0].has_holes());
    return joined.empty() ? Polygon() : joined[0].outer_boundary();
}

// The features' vertices, collinear ones dropped, are the footprint's, in order.
void expectTracesOutline(const FloorPlan &plan, const std::vector<Vec2d> &footprint) {
    std::vector<Vec2d> ring = featureOutline(planFeatures(plan)), corners;
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2d a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
        if (std::abs(cross(b - a, c - b)) > 1e-12) corners.push_back(b);
    }
    ASSERT_EQ(corners.size(), footprint.size());
    auto start = std::find(corners.begin(), corners.end(), footprint[0]);
    ASSERT_NE(start, corners.end());
    std::rotate(corners.begin(), start, corners.end());
    EXPECT_EQ(corners, footprint);
}

void expectPartitionOf(const std::vector<Vec2d> &footprint, const std::vector<Vec2d> &ccw, size_t pieces) {
    FloorPlan plan = partitionFootprint(footprint, kPrototype, {});
    ASSERT_EQ(plan.modules().size(), pieces);
    EXPECT_EQ(plan.kkConnections().size(), pieces - 1);
    Polygon joined = unionOf(plan);
    EXPECT_NEAR(CGAL::to_double(joined.area()), CGAL::to_double(toPolygon(ccw).area()), 1e-9);
    double sum = 0;
    for (const FloorPlanModule &m : plan.modules()) {
        sum += CGAL::to_double(toPolygon(m.outline).area());
        EXPECT_EQ(m.type, "Haus");
        EXPECT_EQ(m.material, "Putz");
    }
    EXPECT_NEAR(sum, CGAL::to_double(toPolygon(ccw).area()), 1e-9);  // no overlap
    expectTracesOutline(plan, ccw);
}

TEST(ModulePartition, LShapedFootprintBecomesTwoModules) {
    std::vector<Vec2d> l = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
    expectPartitionOf(l, l, 2);
}

TEST(ModulePartition, UShapedFootprintBecomesThreeModules) {
    std::vector<Vec2d> u = {{0, 0}, {12, 0}, {12, 8}, {9, 8}, {9, 3}, {3, 3}, {3, 8}, {0, 8}};
    expectPartitionOf(u, u, 3);
}

TEST(ModulePartition, ClockwiseFootprintWithRepeatedAndCollinearPointsIsCleaned) {
    // The L above as a GIS file might give it: clockwise, closed by repeating the first point,
    // with a surveyed point in the middle of a wall.
    std::vector<Vec2d> raw = {{0, 0}, {0, 10}, {4, 10}, {4, 4}, {4, 4}, {7, 4}, {10, 4}, {10, 0}, {0, 0}};
    std::vector<Vec2d> ccw = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
    std::vector<Vec2d> clean = cleanFootprint(raw, {});
    ASSERT_EQ(clean.size(), ccw.size());
    auto start = std::find(clean.begin(), clean.end(), ccw[0]);
    ASSERT_NE(start, clean.end());
    std::rotate(clean.begin(), start, clean.end());
    EXPECT_EQ(clean, ccw);
    expectPartitionOf(raw, ccw, 2);
}

TEST(ModulePartition, LargestPieceIsTheDominantRoot) {
    FloorPlan plan = partitionFootprint({{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}, kPrototype, {});
    int root = plan.dockOf(0) < 0 ? 0 : 1;
    auto area = [&](int m) { return CGAL::to_double(toPolygon(plan.modules()[m].outline).area()); };
    EXPECT_GE(area(root), area(1 - root));
    EXPECT_EQ(plan.kkConnections()[0].dominant, root);
}

TEST(ModulePartition, BadFootprintsAreRejectedWithTheirPlace) {
    FileLoc loc{"town.osm", 120, 5};
    auto errorOf = [&](const std::vector<Vec2d> &footprint) {
        try {
            partitionFootprint(footprint, kPrototype, loc);
        } catch (const InputError &e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(errorOf({{0, 0}, {1, 1}, {2, 2}, {0, 0}}),
              "town.osm:120:5: the footprint has 2 vertices that are not collinear, it needs 3");
    EXPECT_EQ(errorOf({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), "town.osm:120:5: the footprint crosses itself");
}

TEST(ModulePartition, LargeFootprintFallsBackToTheApproximatePartition) {
    // A comb of 9 teeth on a common base: 36 vertices, above kOptimalPartitionMaxVertices.
    std::vector<Vec2d> comb = {{0, 0}, {17, 0}};
    for (int i = 8; i >= 1; --i) {
        comb.push_back({2.0 * i + 1, 5});
        comb.push_back({2.0 * i, 5});
        comb.push_back({2.0 * i, 2});
        comb.push_back({2.0 * i - 1, 2});
    }
    comb.push_back({1, 5});
    comb.push_back({0, 5});
    std::vector<Vec2d> clean = cleanFootprint(comb, {});
    ASSERT_GT(clean.size(), kOptimalPartitionMaxVertices);
    FloorPlan plan = partitionFootprint(comb, kPrototype, {});
    EXPECT_EQ(plan.kkConnections().size() + 1, plan.modules().size());
    EXPECT_NEAR(CGAL::to_double(unionOf(plan).area()), CGAL::to_double(toPolygon(clean).area()), 1e-9);
    expectTracesOutline(plan, clean);
}

}  // namespace
}  // namespace veduta
