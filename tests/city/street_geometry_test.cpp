// Street surfaces: carriageways joined at their nodes, sidewalks around them, kerbs between,
// and what a block keeps for its buildings.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "city/generate_city.h"
#include "city/osm_import.h"
#include "city/street_geometry.h"
#include "test_paths.h"

namespace veduta {
namespace {

float area(const Mesh &m, StreetSurface surface) {
    float sum = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != surface) continue;
        const Vec3f &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
                    &c = m.positions[m.indices[3 * t + 2]];
        sum += 0.5f * length(cross(b - a, c - a));
    }
    return sum;
}

// The carriageway with its junctions.
float road(const Mesh &m) { return area(m, StreetCarriageway) + area(m, StreetJunction); }

// The area of the streets and their sidewalks, from the carriageways of streets widened by the
// sidewalks on either side: what the carriageway and sidewalk surfaces must add up to.
float outerArea(StreetNetwork network) {
    StreetStyle style;
    for (auto &s : network.streets) s.width += 2 * style.sidewalkWidth;
    StreetStyle none;
    none.sidewalkWidth = 0.001f;
    return road(streetGeometry(network, none));
}

TEST(StreetGeometry, OneStreetIsARibbonWithRoundEndsAndSidewalks) {
    StreetNetwork network{{{0, 0}, {100, 0}}, {{0, 1, 8}}, 0};
    Mesh m = streetGeometry(network);
    float joint = kPi * 16 / std::cos(kPi / 16);  // the 16-gons round about r = 4
    EXPECT_GT(area(m, StreetCarriageway), 800 + 0.95f * kPi * 16);
    EXPECT_LT(area(m, StreetCarriageway), 800 + joint * 1.01f);
    // 2.5 m on either side along the street, and round the ends.
    EXPECT_GT(area(m, StreetSidewalk), 2 * 2.5f * 100);
    EXPECT_LT(area(m, StreetSidewalk), 2 * 2.5f * 100 + kPi * 6.5f * 6.5f * 1.03f);
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const Vec3f &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
                    &c = m.positions[m.indices[3 * t + 2]];
        Vec3f n = cross(b - a, c - a);
        ASSERT_GT(length(n), 0) << "degenerate triangle " << t;
        if (m.triangleMaterials[t] == StreetKerb) {
            EXPECT_NEAR(n.z, 0, 1e-6f * length(n));
            EXPECT_NEAR(a.z + b.z + c.z, 2 * 0.01f + 0.13f, 0.2f);  // between road and pavement
            EXPECT_GT(dot(n, m.normals[m.indices[3 * t]]), 0) << "winding agrees with the normal";
        } else {
            EXPECT_GT(n.z, 0) << "faces up";
            EXPECT_FLOAT_EQ(a.z, m.triangleMaterials[t] == StreetSidewalk ? 0.13f : 0.01f);
        }
    }
}

TEST(StreetGeometry, StreetsMeetInOneSurfaceWithoutOverlaps) {
    // A crossroads: four streets from one node.
    StreetNetwork network{
        {{0, 0}, {50, 0}, {-50, 0}, {0, 50}, {0, -50}}, {{0, 1, 8}, {0, 2, 8}, {0, 3, 8}, {0, 4, 8}}, 0};
    Mesh m = streetGeometry(network);
    // Four 50 m arms of 8 m overlap in the middle: the union counts the middle once.
    float carriageway = road(m);
    EXPECT_LT(carriageway, 4 * 50 * 8 + 4 * kPi * 16);
    EXPECT_GT(carriageway, 4 * 50 * 8 - 4 * 4 * 8 + 2 * kPi * 16 * 0.9f);
    // The sidewalks are the widened union minus the carriageway: no surface is counted twice.
    float outer = outerArea(network);
    EXPECT_NEAR(carriageway + area(m, StreetSidewalk), outer, outer * 1e-3f);
}

TEST(StreetGeometry, JunctionsAreWhereThreeOrMoreStreetsMeet) {
    // A crossroads of 8 m streets: every point within 4√2 m of the node lies on one of them, so
    // the junction holds that circle, within the 16-gon round it (circumscribed, as the joints
    // are; its corners at 45° just miss the streets).
    StreetNetwork cross{
        {{0, 0}, {50, 0}, {-50, 0}, {0, 50}, {0, -50}}, {{0, 1, 8}, {0, 2, 8}, {0, 3, 8}, {0, 4, 8}}, 0};
    Mesh m = streetGeometry(cross);
    float reach = kJunctionReach * 4;
    EXPECT_GT(area(m, StreetJunction), kPi * reach * reach);
    EXPECT_LE(area(m, StreetJunction), 16 * reach * reach * std::tan(kPi / 16));
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != StreetJunction) continue;
        for (int k = 0; k < 3; ++k) EXPECT_LE(length(m.positions[m.indices[3 * t + k]]), reach * 1.03f);
    }
    // A bend of two streets is no junction.
    StreetNetwork bend{{{0, 0}, {50, 0}, {0, 50}}, {{0, 1, 8}, {0, 2, 8}}, 0};
    EXPECT_EQ(area(streetGeometry(bend), StreetJunction), 0);
}

TEST(StreetGeometry, AStreetOfNoLengthIsSkipped) {
    StreetNetwork network{{{0, 0}, {0, 0}, {10, 0}}, {{0, 1, 6}, {1, 2, 6}}, 2};
    Mesh m = streetGeometry(network);
    EXPECT_GT(m.triangleCount(), 0u);
    for (const Vec3f &p : m.positions) EXPECT_GE(p.z, 2);
}

TEST(StreetGeometry, ABlockOnTheStreetsCentrelinesKeepsWhatTheSidewalksLeave) {
    // A 60 × 40 block whose outline is the centreline of 8 m streets on all four sides.
    std::vector<Vec2f> block{{0, 0}, {60, 0}, {60, 40}, {0, 40}};
    StreetNetwork network{block, {{0, 1, 8}, {1, 2, 8}, {2, 3, 8}, {3, 0, 8}}, 0};
    std::vector<BuildableArea> areas = buildableAreas(block, network);
    ASSERT_EQ(areas.size(), 1u);
    const BuildableArea &area = areas[0];
    float minX = 1e9f, maxX = -1e9f, minY = 1e9f, maxY = -1e9f;
    for (Vec2f p : area.outline) {
        minX = std::min(minX, p.x);
        maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }
    EXPECT_NEAR(minX, 6.5f, 1e-3f);  // half the street and the sidewalk
    EXPECT_NEAR(maxX, 53.5f, 1e-3f);
    EXPECT_NEAR(minY, 6.5f, 1e-3f);
    EXPECT_NEAR(maxY, 33.5f, 1e-3f);
    for (bool street : area.streetEdges) EXPECT_TRUE(street);

    // A street along one side only: the other edges are not street edges.
    StreetNetwork one{block, {{0, 1, 8}}, 0};
    std::vector<BuildableArea> rest = buildableAreas(block, one);
    ASSERT_EQ(rest.size(), 1u);
    int streetEdges = 0;
    for (bool street : rest[0].streetEdges) streetEdges += street;
    EXPECT_GE(streetEdges, 1);
    EXPECT_LE(streetEdges, 3);  // the long edge, and perhaps the short bevels of the round end
}

// Every triangle indexes a vertex of the mesh, and the road covers at least the longest
// street's ribbon and at most all ribbons and joints together.
void expectWholeSurface(const StreetNetwork &network, const Mesh &m) {
    for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
    float longest = 0, pieces = 0;
    for (const StreetNetwork::Street &s : network.streets) {
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
        float ribbon = std::hypot(b.x - a.x, b.y - a.y) * s.width;
        longest = std::max(longest, ribbon);
        pieces += ribbon + 2 * kPi * s.width * s.width / 4 / std::cos(kPi / kStreetJointSides);
    }
    EXPECT_GT(road(m), 0.999f * longest);
    EXPECT_LT(road(m), 1.001f * pieces);
}

// Outlines whose corners a float cannot tell apart: the diagonal CityData street that made
// the float triangulation of rounded outlines crash, and random networks that cross.
TEST(StreetGeometry, DiagonalAndCrossingStreetsGiveWholeSurfaces) {
    StreetNetwork diagonal{{{19.955f, 120.477f}, {268.778f, 286.421f}}, {{0, 1, 20}}, 0};
    expectWholeSurface(diagonal, streetGeometry(diagonal));
    std::mt19937 random(17);
    std::uniform_real_distribution<float> coordinate(0, 300), width(2, 20);
    for (int n = 0; n < 10; ++n) {
        StreetNetwork network;
        for (int k = 0; k < 8; ++k) network.nodes.push_back({coordinate(random), coordinate(random)});
        for (uint32_t k = 0; k + 1 < 8; ++k) network.streets.push_back({k, uint32_t(random() % 8), width(random)});
        SCOPED_TRACE(n);
        expectWholeSurface(network, streetGeometry(network));
    }
}

// Found by fuzz/osm: at a gentle bend the bevel's corners, rounded to float, fell onto one line
// with the node, and CGAL refused the degenerate triangle.
TEST(StreetGeometry, ADegenerateBevelIsLeftOut) {
    CityData city = importOsm(test::sourceFile("fuzz/regressions/osm/degenerate_bevel_triangle.osm"), {});
    Mesh mesh = streetGeometry(streetNetworkOf(city));
    EXPECT_GT(mesh.triangleCount(), 0u);
}

// Found by fuzz/osm: CGAL's difference of the sidewalks and the carriageway of this town (a
// street run out 4.5 km east) left a face with two outer boundaries; the sidewalks are the
// symmetric difference now.
TEST(StreetGeometry, SidewalksAreWhatTheWidenedStreetsAddToTheCarriageway) {
    CityData city = importOsm(test::sourceFile("fuzz/regressions/osm/difference_face_of_two_outer_boundaries.osm"), {});
    StreetNetwork network = streetNetworkOf(city);
    Mesh mesh = streetGeometry(network);
    float outer = outerArea(network);
    EXPECT_NEAR(road(mesh) + area(mesh, StreetSidewalk), outer, outer * 1e-3f);
    EXPECT_GT(area(mesh, StreetJunction), 0);
}

}  // namespace
}  // namespace veduta
