// Buildings as meshes at their levels of detail (digest-003 §3.2–3.5, §8.2): the ear clipping's
// n − 2 counter-clockwise triangles, 14 triangles for the coarsest gable house on four corners,
// outward normals, a closed shell, a four-storey house with its rooms under about 3,000, shared
// corners, wall textures that run on round a storey, corridor floors where the rooms leave the
// storey, and the stairs in the stairwell.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "slg/building_mesh.h"
#include "slg/ear_clipping.h"
#include "slg/stairs.h"
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

// A terraced house of four storeys on a lot between two neighbours, planned down to its rooms.
std::optional<BuildingPlan> fourStoreyHouse() {
    PlanShape lot{{{0, 0}, {14, 0}, {14, 40}, {0, 40}},
                  {EdgeLocation::Street, EdgeLocation::NeighbourArea, EdgeLocation::Gap, EdgeLocation::NeighbourArea}};
    BuildingPlanParameters p;
    p.placement.buildingArea = 125;
    p.placement.sideRatio = 1.2;
    p.placement.minimumSide = lengthLimits(storeyLevel()).minimum;
    p.storey = storeyLevel();
    p.apartment = apartmentLevel();
    p.storeys = 4;
    return planBuilding(lot, fourSides(lot.points, 1), p, 1, 7);
}

TEST(BuildingMesh, AFourStoreyHouseWithItsRoomsStaysUnderThreeThousandTriangles) {
    auto plan = fourStoreyHouse();
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

double areaOf(const Mesh &mesh, size_t t) { return length(normalOf(mesh, t)) / 2; }

Vec3f corner(const Mesh &mesh, size_t t, int k) { return mesh.positions[mesh.indices[3 * t + size_t(k)]]; }

// The mesh with three corners of its own for every triangle, as it was before welding.
// The distance along a ray to triangle t, if it meets it (Möller and Trumbore).
std::optional<float> hitDistance(const Mesh &mesh, size_t t, Vec3f origin, Vec3f direction) {
    Vec3f a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
          c = mesh.positions[mesh.indices[3 * t + 2]];
    Vec3f e1 = b - a, e2 = c - a, p = cross(direction, e2);
    float det = dot(e1, p);
    if (std::abs(det) < 1e-9f) return std::nullopt;
    Vec3f s = origin - a, q = cross(s, e1);
    float u = dot(s, p) / det, v = dot(direction, q) / det, d = dot(e2, q) / det;
    if (u < 0 || v < 0 || u + v > 1 || d <= 0) return std::nullopt;
    return d;
}

// §3.5: at the nearest level a room shows through the glass. Looking in through the middle of
// every window, the first surface behind the pane lies deeper than the wall: the room's far
// side, not the back of its own wall.
TEST(BuildingMesh, EveryWindowLooksIntoItsRoom) {
    auto plan = fourStoreyHouse();
    ASSERT_TRUE(plan);
    BuildingShape shape;
    MaterialId glass = 2, interior = 5;
    Mesh mesh = buildingMesh(*plan, shape, BuildingLod::Rooms, {1, glass, 3, 4, interior});
    int windows = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (mesh.triangleMaterials[t] != glass) continue;
        Vec3f inward = normalize(normalOf(mesh, t)) * -1.0f;
        Vec3f centre = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                        mesh.positions[mesh.indices[3 * t + 2]]) *
            (1.0f / 3);
        float nearest = 1e30f;
        for (size_t other = 0; other < mesh.triangleCount(); ++other)
            if (mesh.triangleMaterials[other] == interior)
                if (auto d = hitDistance(mesh, other, centre, inward)) nearest = std::min(nearest, *d);
        EXPECT_GT(nearest, shape.wallThickness + 0.5) << "pane triangle " << windows;
        ++windows;
    }
    EXPECT_GE(windows, 4 * 2 * 2);
}

Mesh unwelded(const Mesh &mesh) {
    Mesh soup;
    for (uint32_t i : mesh.indices) {
        soup.indices.push_back(uint32_t(soup.positions.size()));
        soup.positions.push_back(mesh.positions[i]);
        soup.uvs.push_back(mesh.uvs[i]);
    }
    soup.triangleMaterials = mesh.triangleMaterials;
    return soup;
}

TEST(BuildingMesh, PiecesShareTheirCornersAndNoTriangleIsLost) {
    auto plan = fourStoreyHouse();
    ASSERT_TRUE(plan);
    BuildingShape shape;
    shape.roof = RoofKind::Flat;
    Mesh mesh = buildingMesh(*plan, shape, BuildingLod::Storeys, {1, 2, 3, 4, 5});
    // Unwelded, every triangle has three corners of its own; a quad's two triangles share two,
    // and the quads of a wall and the storeys above their edges. A pane or the door is a motif
    // of its own (its image stretched over it): its two triangles keep four corners of their own.
    auto stretched =
        size_t(std::ranges::count_if(mesh.triangleMaterials, [](MaterialId m) { return m == 2 || m == 3; }));
    EXPECT_LT(mesh.vertexCount(), mesh.triangleCount() + 2 * stretched);
    EXPECT_EQ(weldVertices(unwelded(mesh)).vertexCount(), mesh.vertexCount()) << "nothing left to merge";
    // Every triangle keeps three corners, and together they are the walls of every storey and
    // the flat roof: welding merged corners only.
    double area = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const uint32_t *i = &mesh.indices[3 * t];
        EXPECT_TRUE(i[0] != i[1] && i[1] != i[2] && i[2] != i[0]) << t;
        EXPECT_GT(areaOf(mesh, t), 0) << t;
        area += areaOf(mesh, t);
    }
    const PlanShape &footprint = plan->placement.footprint;
    double perimeter = 0;
    for (size_t e = 0; e < footprint.size(); ++e) perimeter += footprint.edgeLength(e);
    double expected = perimeter * plan->storeys * shape.storeyHeight + signedArea(footprint.points);
    EXPECT_NEAR(area, expected, 1e-5 * expected);
}

TEST(BuildingMesh, TheWallTextureRunsOnRoundTheCorners) {
    Polygon2d footprint = {{0, 0}, {10, 0}, {10, 12}, {0, 12}};
    Mesh mesh = buildingMesh(boxPlan(footprint, 2), {}, BuildingLod::Storeys, {1, 2, 3, 4, 5});
    // u is the way walked round the storey from point 0 in motifs (a storey's height, 3 m), so
    // both walls at a corner agree there; at point 0 itself the last wall ends the perimeter on
    // (the seam).
    std::vector<std::vector<float>> expected = {{0, 44 / 3.0f}, {10 / 3.0f}, {22 / 3.0f}, {32 / 3.0f}};
    for (size_t c = 0; c < footprint.size(); ++c) {
        std::vector<float> us;
        std::set<std::pair<float, float>> walls;  // their outward directions
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            Vec3f n = normalOf(mesh, t);
            if (mesh.triangleMaterials[t] != 1) continue;  // the walls', not the gables'
            for (int k = 0; k < 3; ++k) {
                Vec3f p = corner(mesh, t, k);
                if (p.x != float(footprint[c].x) || p.y != float(footprint[c].y)) continue;
                us.push_back(mesh.uvs[mesh.indices[3 * t + size_t(k)]].x);
                Vec3f out = normalize(n);
                walls.insert({std::round(out.x), std::round(out.y)});
            }
        }
        EXPECT_EQ(walls.size(), 2u) << c;
        for (float u : us)
            EXPECT_TRUE(std::ranges::any_of(expected[c], [&](float e) { return std::abs(u - e) < 1e-5f; }))
                << c << ": " << u;
        for (float e : expected[c])
            EXPECT_TRUE(std::ranges::any_of(us, [&](float u) { return std::abs(u - e) < 1e-5f; })) << c << ": " << e;
    }
}

// The simple mapping (§3.3): a door's and a pane's image covers it once, whatever its size.
TEST(BuildingMesh, DoorsAndPanesShowTheirImageOnce) {
    auto plan = fourStoreyHouse();
    ASSERT_TRUE(plan);
    Mesh mesh = buildingMesh(*plan, {}, BuildingLod::Storeys, {1, 2, 3, 4, 5});
    int quads = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (mesh.triangleMaterials[t] != 2 && mesh.triangleMaterials[t] != 3) continue;
        for (int k = 0; k < 3; ++k) {
            Vec2f uv = mesh.uvs[mesh.indices[3 * t + size_t(k)]];
            EXPECT_TRUE(uv.x == 0 || uv.x == 1) << uv.x;
            EXPECT_TRUE(uv.y == 0 || uv.y == 1) << uv.y;
        }
        ++quads;
    }
    EXPECT_GT(quads, 16);
}

using Triangle2 = std::array<Vec2d, 3>;

Triangle2 flat(const Mesh &mesh, size_t t) {
    Triangle2 out;
    for (int k = 0; k < 3; ++k) out[size_t(k)] = {corner(mesh, t, k).x, corner(mesh, t, k).y};
    return out;
}

// Two triangles overlap in more than a rounding when no side of either separates them.
bool overlap(const Triangle2 &a, const Triangle2 &b) {
    constexpr double kRounding = 1e-5;
    for (const Triangle2 *t : {&a, &b})
        for (size_t i = 0; i < 3; ++i) {
            Vec2d side = (*t)[(i + 1) % 3] - (*t)[i];
            if (length(side) == 0) return false;
            Vec2d n = normalized(leftNormal(side));
            auto [aLow, aHigh] = std::ranges::minmax({dot(a[0], n), dot(a[1], n), dot(a[2], n)});
            auto [bLow, bHigh] = std::ranges::minmax({dot(b[0], n), dot(b[1], n), dot(b[2], n)});
            if (aHigh <= bLow + kRounding || bHigh <= aLow + kRounding) return false;
        }
    return true;
}

// The upward triangles of a mesh at height z, as the plan sees them.
std::vector<Triangle2> floorAt(const Mesh &mesh, double z) {
    std::vector<Triangle2> floor;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f n = normalOf(mesh, t);
        bool level = std::ranges::all_of(std::array{0, 1, 2}, [&](int k) { return corner(mesh, t, k).z == float(z); });
        if (level && n.z > 0) floor.push_back(flat(mesh, t));
    }
    return floor;
}

double areaOf(const Triangle2 &t) { return cross(t[1] - t[0], t[2] - t[0]) / 2; }

TEST(BuildingMesh, TheCorridorsFloorWhatTheRoomsLeaveOfAStorey) {
    auto plan = fourStoreyHouse();
    ASSERT_TRUE(plan);
    BuildingShape shape;
    Mesh mesh = buildingMesh(*plan, shape, BuildingLod::Rooms, {1, 2, 3, 4, 5});
    std::vector<Triangle2> floor = floorAt(mesh, shape.base);
    double area = 0;
    for (size_t i = 0; i < floor.size(); ++i) {
        area += areaOf(floor[i]);
        for (size_t j = 0; j < i; ++j) EXPECT_FALSE(overlap(floor[i], floor[j])) << i << " " << j;
    }
    // The spaces of the plan — the rooms, the apartments' corridors, the house corridor — each
    // lose a strip inside their walls: the wall thickness t along the shell, t/2 elsewhere. On a
    // plan of right angles the strips of a space's sides add up to what it loses but at its
    // corners, where two strips overlap (a convex corner, counted twice) or leave a square
    // between them (a reflex one): at most t² a corner either way.
    const PlanShape &shell = plan->placement.footprint;
    double t = shape.wallThickness, strips = 0;
    size_t corners = 0;
    auto addSpace = [&](const Polygon2d &ring) {
        for (size_t e = 0; e < ring.size(); ++e) {
            Vec2d a = ring[e], b = ring[(e + 1) % ring.size()];
            bool onShell = distanceToBoundary(shell.points, a) < 1e-6 && distanceToBoundary(shell.points, b) < 1e-6 &&
                distanceToBoundary(shell.points, (a + b) * 0.5) < 1e-6;
            strips += (onShell ? t : t / 2) * length(b - a);
        }
        corners += turningPoints(ring).size();
    };
    std::vector<PlanShape> outlines;
    double corridors = 0;
    auto addCorridor = [&](const Polygon2d &outline, const std::vector<PlanShape> &faces) {
        for (const auto &piece : corridorPieces(outline, faces))
            for (const Polygon2d &ring : piece) {
                addSpace(ring);
                corridors += signedArea(ring);
            }
    };
    for (const ApartmentPlan &apartment : plan->storey.apartments) {
        outlines.push_back(apartment.outline);
        for (const PlanShape &room : apartment.rooms) addSpace(room.points);
        addCorridor(apartment.outline.points, apartment.rooms);
    }
    addCorridor(shell.points, outlines);
    double walls = signedArea(shell.points) - area, slack = double(corners) * t * t;
    EXPECT_NEAR(walls, strips, slack);
    EXPECT_GT(corridors, 2 * slack) << "the bound would not see the corridors missing";
    std::cout << "ground floor: " << area << " m² of " << signedArea(shell.points) << " m², walls " << walls
              << " m² against strips of " << strips << " ± " << slack << " m², corridors " << corridors << " m²\n";
}

TEST(BuildingMesh, TheStairwellClimbsFromEveryStoreyButTheTop) {
    auto plan = fourStoreyHouse();
    ASSERT_TRUE(plan);
    BuildingShape shape;
    shape.roof = RoofKind::Flat;
    std::optional<Polygon2d> well;
    for (const ApartmentPlan &apartment : plan->storey.apartments)
        if (apartment.stairwell)
            if (auto floor =
                    insideWalls(apartment.rooms[*apartment.stairwell], plan->placement.footprint, shape.wallThickness))
                well = floor->points;
    ASSERT_TRUE(well);
    auto flight = straightFlight(*well, shape.storeyHeight);
    ASSERT_TRUE(flight);

    Mesh mesh = buildingMesh(*plan, shape, BuildingLod::Rooms, {1, 2, 3, 4, 5});
    double top = shape.base + plan->storeys * shape.storeyHeight;
    std::vector<float> treads, ceilings;
    int floors = 0, risers = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        Vec3f a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2), n = normalOf(mesh, t);
        Vec2d middle = centreOf(mesh, t);
        if (sideOf(*well, middle) != Side::Inside || std::max({a.z, b.z, c.z}) >= float(top)) continue;
        for (int k = 0; k < 3; ++k)
            EXPECT_LE(distanceOutside(*well, {corner(mesh, t, k).x, corner(mesh, t, k).y}), 1e-5);
        float low = std::min({a.z, b.z, c.z}), high = std::max({a.z, b.z, c.z});
        if (n.z < 0) ceilings.push_back(low);
        else if (n.z > 0 && low == float(shape.base)) ++floors;
        else if (n.z > 0) treads.push_back(low);
        else if (std::abs(high - low - flight->riser) < 1e-5) {
            ++risers;
            EXPECT_LT(dot(Vec2d{n.x, n.y}, flight->up), 0) << "a riser faces down the flight";
        }
    }
    // The ground floor's floor and the top storey's ceiling, each the room in n − 2 triangles;
    // between them nothing across the shaft but the steps, a tread and a riser each.
    int flights = plan->storeys - 1, triangles = int(well->size()) - 2;
    EXPECT_EQ(floors, triangles);
    EXPECT_EQ(ceilings.size(), size_t(triangles));
    for (float z : ceilings) EXPECT_NEAR(z, top - shape.slab, 1e-5);
    EXPECT_EQ(risers, 2 * flight->risers * flights);
    std::vector<float> expected;
    for (int storey = 0; storey < flights; ++storey)
        for (int step = 1; step <= flight->risers; ++step)
            for (int k = 0; k < 2; ++k)
                expected.push_back(float(shape.base + storey * shape.storeyHeight + step * flight->riser));
    std::ranges::sort(treads);
    ASSERT_EQ(treads.size(), expected.size());
    for (size_t i = 0; i < treads.size(); ++i) EXPECT_NEAR(treads[i], expected[i], 1e-5) << i;
    // Each flight's last tread is the next floor.
    EXPECT_NEAR(treads.back(), shape.base + flights * shape.storeyHeight, 1e-5);
}

}  // namespace
}  // namespace veduta
