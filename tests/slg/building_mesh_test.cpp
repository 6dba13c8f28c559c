// Buildings as meshes at their levels of detail (digest-003 §3.2–3.5, §8.2): the ear clipping's
// n − 2 counter-clockwise triangles, 14 triangles for the coarsest gable house on four corners,
// outward normals, a closed shell, and a four-storey house with its rooms under about 3,000.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "slg/building_mesh.h"
#include "slg/ear_clipping.h"
#include "slg/thesis_levels.h"

namespace veduta {
namespace {

double triangleArea(Vec2d a, Vec2d b, Vec2d c) { return cross(b - a, c - a) / 2; }

void expectTriangulated(const Polygon2d &polygon) {
    auto triangles = clipEars(polygon);
    ASSERT_EQ(triangles.size(), polygon.size() - 2);
    double area = 0;
    for (auto [i, j, k] : triangles) {
        double a = triangleArea(polygon[i], polygon[j], polygon[k]);
        EXPECT_GE(a, 0);
        area += a;
    }
    EXPECT_NEAR(area, signedArea(polygon), 1e-9 * signedArea(polygon));
}

TEST(EarClipping, SimplePolygonsGiveNMinusTwoCounterClockwiseTriangles) {
    expectTriangulated({{0, 0}, {4, 0}, {4, 3}, {0, 3}});
    expectTriangulated({{0, 0}, {80, 0}, {80, 40}, {40, 40}, {40, 80}, {0, 80}});
    expectTriangulated({{0, 0}, {5, 0}, {10, 0}, {10, 5}, {10, 10}, {5, 10}, {0, 10}, {0, 5}});  // points on the sides
    Polygon2d star;
    for (int i = 0; i < 24; ++i) {
        double r = i % 2 ? 4 : 10, angle = i * std::numbers::pi / 12;
        star.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    expectTriangulated(star);
}

BuildingPlan boxPlan(Polygon2d footprint, int storeys) {
    BuildingPlan plan;
    plan.placement.footprint = {footprint, std::vector<EdgeLocation>(footprint.size(), EdgeLocation::Street)};
    plan.storeys = storeys;
    plan.storey.entrance = (footprint[0] + footprint[1]) * 0.5;
    return plan;
}

Vec3f normalOf(const Mesh &mesh, size_t t) {
    Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
          c = mesh.positions[mesh.indices[3 * t + 2]];
    return cross(b - a, c - a);
}

Vec2d centreOf(const Mesh &mesh, size_t t) {
    Vec3f sum = mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
        mesh.positions[mesh.indices[3 * t + 2]];
    return {sum.x / 3, sum.y / 3};
}

// Every triangle faces out: a wall's normal leads out of the footprint, a roof's up.
void expectOutward(const Mesh &mesh, const Polygon2d &footprint) {
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f n = normalOf(mesh, t);
        if (std::abs(n.z) > 1e-6 * length(n)) {
            EXPECT_GT(n.z, 0) << t;
            continue;
        }
        Vec2d outwards = centreOf(mesh, t) + normalized(Vec2d{n.x, n.y}) * 0.01;
        EXPECT_EQ(sideOf(footprint, outwards), Side::Outside) << t;
    }
}

using Point3 = std::tuple<float, float, float>;

// The edges of a mesh used by one triangle only (by position, either way round).
std::map<std::pair<Point3, Point3>, int> openEdges(const Mesh &mesh) {
    std::map<std::pair<Point3, Point3>, int> uses;
    for (size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            Vec3f a = mesh.positions[mesh.indices[3 * t + k]], b = mesh.positions[mesh.indices[3 * t + (k + 1) % 3]];
            Point3 p{a.x, a.y, a.z}, q{b.x, b.y, b.z};
            ++uses[std::minmax(p, q)];
        }
    std::erase_if(uses, [](const auto &u) { return u.second != 1; });
    return uses;
}

TEST(BuildingMesh, TheCoarsestGableHouseOnFourCornersIsFourteenTriangles) {
    Polygon2d footprint = {{0, 0}, {10, 0}, {10, 12}, {0, 12}};
    BuildingShape shape;
    for (RoofOrientation orientation : {RoofOrientation::Traufstaendig, RoofOrientation::Giebelstaendig}) {
        shape.orientation = orientation;
        Mesh mesh = buildingMesh(boxPlan(footprint, 4), shape, BuildingLod::Box, {});
        EXPECT_EQ(mesh.triangleCount(), 14u);
        expectOutward(mesh, footprint);
        // Closed but for its bottom: the four ground edges are the only ones used once.
        auto open = openEdges(mesh);
        EXPECT_EQ(open.size(), 4u);
        for (const auto &[edge, uses] : open) {
            EXPECT_EQ(std::get<2>(edge.first), 0);
            EXPECT_EQ(std::get<2>(edge.second), 0);
        }
    }
}

TEST(BuildingMesh, PointsOnTheSidesMakeNoMoreWallsAtTheCoarsestLevel) {
    Polygon2d footprint = {{0, 0}, {5, 0}, {10, 0}, {10, 12}, {0, 12}};
    BuildingShape shape;
    shape.roof = RoofKind::Flat;
    EXPECT_EQ(buildingMesh(boxPlan(footprint, 2), shape, BuildingLod::Box, {}).triangleCount(), 8u + 3u);
    shape.roof = RoofKind::Tent;
    Mesh tent = buildingMesh(boxPlan(footprint, 2), shape, BuildingLod::Box, {});
    EXPECT_EQ(tent.triangleCount(), 8u + 4u);
    expectOutward(tent, footprint);
}

TEST(BuildingMesh, AFourStoreyHouseWithItsRoomsStaysUnderThreeThousandTriangles) {
    PlanShape lot{{{0, 0}, {14, 0}, {14, 40}, {0, 40}},
                  {EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap, EdgeLocation::NeighbourArea}};
    BuildingPlanParameters p;
    p.placement.buildingArea = 125;
    p.placement.sideRatio = 1.2;
    p.placement.minimumSide = lengthLimits(storeyLevel()).minimum;
    p.storey = storeyLevel();
    p.apartment = apartmentLevel();
    p.storeys = 4;
    auto plan = planBuilding(lot, fourSides(lot.points, 1), p, 1, 7);
    ASSERT_TRUE(plan);
    BuildingMaterials m{1, 2, 3, 4, 5};
    BuildingShape shape;
    Mesh storeys = buildingMesh(*plan, shape, BuildingLod::Storeys, m);
    Mesh rooms = buildingMesh(*plan, shape, BuildingLod::Rooms, m);
    Mesh box = buildingMesh(*plan, shape, BuildingLod::Box, m);
    EXPECT_LE(rooms.triangleCount(), 3000u);
    EXPECT_GT(rooms.triangleCount(), storeys.triangleCount());
    EXPECT_GT(storeys.triangleCount(), box.triangleCount());
    expectOutward(storeys, plan->placement.footprint.points);
    auto count = [](const Mesh &mesh, MaterialId id) { return std::ranges::count(mesh.triangleMaterials, id); };
    EXPECT_EQ(count(storeys, 3), 2) << "one house door";
    // Windows on the street and the back, none on the walls against the neighbours: four storeys
    // of two walls, each with at least one window of two triangles.
    EXPECT_GE(count(storeys, 2), 4 * 2 * 2);
    for (size_t t = 0; t < storeys.triangleCount(); ++t) {
        if (storeys.triangleMaterials[t] != 2) continue;
        Vec3f n = normalOf(storeys, t);
        EXPECT_LT(std::abs(n.x), 1e-3 * length(n)) << "glass only on the front and back";
    }
    EXPECT_GT(count(rooms, 5), 0);
    std::cout << "four storeys: " << box.triangleCount() << " (box), " << storeys.triangleCount() << " (storeys), "
              << rooms.triangleCount() << " (rooms) triangles\n";
}

}  // namespace
}  // namespace veduta
