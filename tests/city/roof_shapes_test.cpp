#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "city/roof_shapes.h"
#include "city/roofs.h"
#include "core/hash.h"

namespace veduta {
namespace {

using Point = std::tuple<float, float, float>;
using Edge = std::pair<Point, Point>;

constexpr float kEaves = 10;

RoofFootprint quad() { return {{{0, 0}, {14, -2}, {16, 9}, {2, 11}}, {}, 1}; }
RoofFootprint rectangle() { return {{{0, 0}, {20, 0}, {20, 12}, {0, 12}}, {}, 1}; }
RoofFootprint lShape() { return {{{0, 0}, {24, 0}, {24, 12}, {12, 12}, {12, 24}, {0, 24}}, {}, 1}; }
RoofFootprint tShape() { return {{{0, 0}, {30, 0}, {30, 10}, {20, 10}, {20, 25}, {10, 25}, {10, 10}, {0, 10}}, {}, 1}; }
RoofFootprint uShape() { return {{{0, 0}, {30, 0}, {30, 20}, {22, 20}, {22, 8}, {8, 8}, {8, 20}, {0, 20}}, {}, 1}; }
RoofFootprint courtyard() {
    return {{{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {{{10, 10}, {10, 20}, {20, 20}, {20, 10}}}, 1};
}

std::vector<std::vector<Vec2f>> ringsOf(const RoofFootprint &footprint) {
    std::vector<std::vector<Vec2f>> rings{footprint.outer};
    rings.insert(rings.end(), footprint.holes.begin(), footprint.holes.end());
    return rings;
}

Vec3f corner(const Mesh &m, size_t t, int k) { return m.positions[m.indices[3 * t + size_t(k)]]; }
Point key(const Vec3f &p) { return {p.x, p.y, p.z}; }
Vec3f crossOf(const Mesh &m, size_t t) {
    return cross(corner(m, t, 1) - corner(m, t, 0), corner(m, t, 2) - corner(m, t, 0));
}
float area(const Mesh &m, size_t t) { return 0.5f * length(crossOf(m, t)); }

float uvArea(const Mesh &m, size_t t) {
    const uint32_t *idx = &m.indices[3 * t];
    Vec2f a = m.uvs[idx[0]], b = m.uvs[idx[1]], c = m.uvs[idx[2]];
    return 0.5f * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Twice the signed area in double, counter-clockwise positive.
double ringArea(const std::vector<Vec2f> &ring) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2f a = ring[i], b = ring[(i + 1) % ring.size()];
        sum += double(a.x) * b.y - double(b.x) * a.y;
    }
    return sum / 2;
}

double footprintArea(const RoofFootprint &footprint) {
    double total = 0;
    for (const auto &ring : ringsOf(footprint)) total += ringArea(ring);
    return total;
}

double projectedArea(const Mesh &m, size_t t) {
    Vec3f a = corner(m, t, 0), b = corner(m, t, 1), c = corner(m, t, 2);
    return (double(b.x - a.x) * (c.y - a.y) - double(c.x - a.x) * (b.y - a.y)) / 2;
}

// The footprint's floor at the eaves, facing down: with it a roof must close.
Mesh floorAt(const RoofFootprint &footprint, float z) {
    Mesh cap;
    for (const auto &ring : ringsOf(footprint)) {
        for (Vec2f p : ring) cap.positions.push_back(lift(p, z));
    }
    std::vector<uint32_t> up = triangulatePolygonWithHoles(ringsOf(footprint));
    for (size_t t = 0; t < up.size(); t += 3) cap.indices.insert(cap.indices.end(), {up[t], up[t + 2], up[t + 1]});
    return cap;
}

std::map<Edge, int> directedEdges(const Mesh &m) {
    std::map<Edge, int> edges;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) ++edges[{key(corner(m, t, k)), key(corner(m, t, (k + 1) % 3))}];
    }
    return edges;
}

// Every edge used by exactly two triangles, once each way, so the normals agree.
void expectClosedWith(const Mesh &roof, const Mesh &floor) {
    std::map<Edge, int> edges = directedEdges(roof);
    for (const auto &[edge, count] : directedEdges(floor)) edges[edge] += count;
    for (const auto &[edge, count] : edges) {
        EXPECT_EQ(count, 1) << "edge used " << count << " times";
        auto reverse = edges.find({edge.second, edge.first});
        EXPECT_TRUE(reverse != edges.end() && reverse->second == 1) << "an open edge";
    }
}

// The roof's open edges are the footprint's, at the eaves, running as the footprint does.
void expectEavesOn(const Mesh &roof, const RoofFootprint &footprint, float eavesZ) {
    std::map<Edge, int> edges = directedEdges(roof);
    std::set<Edge> open, expected;
    for (const auto &[edge, count] : edges) {
        if (!edges.count({edge.second, edge.first})) open.insert(edge);
    }
    for (const auto &ring : ringsOf(footprint)) {
        for (size_t i = 0; i < ring.size(); ++i) {
            expected.insert({key(lift(ring[i], eavesZ)), key(lift(ring[(i + 1) % ring.size()], eavesZ))});
        }
    }
    EXPECT_EQ(open, expected);
}

// Corners merged where they coincide: a manifold surface (with the eaves as its border) that
// does not cross itself.
void expectNoSelfIntersections(const Mesh &m) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::map<Point, size_t> indexOf;
    std::vector<Kernel::Point_3> points;
    std::vector<std::vector<size_t>> triangles;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        triangles.emplace_back();
        for (int k = 0; k < 3; ++k) {
            Vec3f p = corner(m, t, k);
            auto [it, inserted] = indexOf.insert({key(p), points.size()});
            if (inserted) points.emplace_back(p.x, p.y, p.z);
            triangles.back().push_back(it->second);
        }
    }
    namespace PMP = CGAL::Polygon_mesh_processing;
    ASSERT_TRUE(PMP::is_polygon_soup_a_polygon_mesh(triangles));
    CGAL::Surface_mesh<Kernel::Point_3> surface;
    PMP::polygon_soup_to_polygon_mesh(points, triangles, surface);
    EXPECT_FALSE(PMP::does_self_intersect(surface));
}

double signedVolume(const Mesh &m) {
    double volume = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        Vec3f a = corner(m, t, 0), b = corner(m, t, 1), c = corner(m, t, 2);
        volume += double(dot(a, cross(b, c))) / 6;
    }
    return volume;
}

// Well formed, closed by its floor, pointing outwards, covering the footprint once, not crossing
// itself, with UVs in metres on the covering.
void expectRoofOver(const RoofResult &roof, const RoofFootprint &eaves, float eavesZ) {
    const Mesh &m = roof.mesh;
    ASSERT_GT(m.triangleCount(), 0u);
    ASSERT_EQ(m.normals.size(), m.vertexCount());
    ASSERT_EQ(m.uvs.size(), m.vertexCount());
    ASSERT_EQ(m.triangleMaterials.size(), m.triangleCount());
    double covered = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        EXPECT_GT(area(m, t), 1e-4f) << "triangle " << t;
        Vec3f n = normalize(crossOf(m, t));
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(dot(m.normals[m.indices[3 * t + size_t(k)]], n), 0.999f) << "triangle " << t;
        if (m.triangleMaterials[t] == RoofCovering) {
            EXPECT_GT(n.z, 0) << "triangle " << t;
            EXPECT_NEAR(uvArea(m, t), area(m, t), 1e-3f * area(m, t)) << "triangle " << t;
        }
        if (n.z > 1e-6f) covered += projectedArea(m, t);
    }
    EXPECT_NEAR(covered, footprintArea(eaves), 1e-6 * footprintArea(eaves));
    Mesh floor = floorAt(eaves, eavesZ);
    expectClosedWith(m, floor);
    expectEavesOn(m, eaves, eavesZ);
    expectNoSelfIntersections(m);
    Mesh closed = m;
    closed.append(floor, Transform{});
    EXPECT_GT(signedVolume(closed), 0);
}

size_t edgeCount(const RoofFootprint &footprint) {
    size_t count = 0;
    for (const auto &ring : ringsOf(footprint)) count += ring.size();
    return count;
}

// Covering triangles joined across shared edges into faces of one plane.
size_t planarFaces(const Mesh &m) {
    std::vector<size_t> parent(m.triangleCount());
    for (size_t t = 0; t < parent.size(); ++t) parent[t] = t;
    auto root = [&](size_t t) {
        while (parent[t] != t) t = parent[t];
        return t;
    };
    std::map<std::pair<Point, Point>, size_t> firstUse;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            Point a = key(corner(m, t, k)), b = key(corner(m, t, (k + 1) % 3));
            auto [it, inserted] = firstUse.insert({std::minmax(a, b), t});
            if (!inserted && dot(normalize(crossOf(m, t)), normalize(crossOf(m, it->second))) > 0.9999f) {
                parent[root(t)] = root(it->second);
            }
        }
    }
    std::set<size_t> roots;
    for (size_t t = 0; t < m.triangleCount(); ++t) roots.insert(root(t));
    return roots.size();
}

struct Case {
    const char *name;
    RoofFootprint footprint;
};

std::vector<Case> footprints() {
    return {{"quad", quad()}, {"rectangle", rectangle()}, {"L", lShape()}, {"T", tShape()},
            {"U", uShape()},  {"courtyard", courtyard()}};
}

TEST(RoofShapes, EveryTypeClosesOverEveryFootprint) {
    for (const Case &c : footprints()) {
        for (RoofType type : kRoofTypes) {
            SCOPED_TRACE(fmt::format("{} roof on {}", roofTypeName(type), c.name));
            RoofOptions options{type, 35, 0, 0.8f, -1, 0.5f};
            RoofResult roof = buildRoof(c.footprint, kEaves, options);
            EXPECT_EQ(roof.fallback.has_value(), roof.built != type);
            expectRoofOver(roof, c.footprint, c.footprint.base + kEaves);
        }
    }
}

TEST(RoofShapes, TypesFallBackWhereTheFootprintCannotTakeThem) {
    auto built = [](const RoofFootprint &footprint, RoofType type) {
        return buildRoof(footprint, kEaves, RoofOptions{type, 35, 0, 0.8f, -1, 0.5f}).built;
    };
    EXPECT_EQ(built(quad(), RoofType::Pyramid), RoofType::Pyramid);
    EXPECT_EQ(built(lShape(), RoofType::Pyramid), RoofType::Hip);
    EXPECT_EQ(built(rectangle(), RoofType::Gable), RoofType::Gable);
    EXPECT_EQ(built(uShape(), RoofType::Gable), RoofType::Gable);
    EXPECT_EQ(built(courtyard(), RoofType::Gable), RoofType::Hip);
    EXPECT_EQ(built(courtyard(), RoofType::HalfHip), RoofType::Hip);
    EXPECT_EQ(built(tShape(), RoofType::Mansard), RoofType::Mansard);
    EXPECT_EQ(built(courtyard(), RoofType::Mansard), RoofType::Flat);
    EXPECT_EQ(built(courtyard(), RoofType::Shed), RoofType::Shed);
    RoofResult roof = buildRoof(courtyard(), kEaves, RoofOptions{RoofType::Pyramid, 35, 0, 0.8f, -1, 0.5f});
    ASSERT_TRUE(roof.fallback.has_value());
    EXPECT_NE(roof.fallback->find("pyramid"), std::string::npos) << *roof.fallback;
}

TEST(RoofShapes, HipHasOneFacePerEdge) {
    for (const Case &c : footprints()) {
        SCOPED_TRACE(c.name);
        RoofResult roof = buildRoof(c.footprint, kEaves, RoofOptions{RoofType::Hip, 35, 0, 0.8f, -1, 0.5f});
        ASSERT_EQ(roof.built, RoofType::Hip);
        EXPECT_EQ(planarFaces(roof.mesh), edgeCount(c.footprint));
    }
}

float highest(const Mesh &m) {
    float top = -INFINITY;
    for (const Vec3f &p : m.positions) top = std::max(top, p.z);
    return top;
}

TEST(RoofShapes, SlopesRiseAtThePitch) {
    // 12 m deep at 45°: the ridge is 6 m above the eaves, the shed's high side 12 m.
    RoofFootprint house = rectangle();
    float eavesZ = house.base + kEaves;
    for (auto [type, rise] : {std::pair{RoofType::Hip, 6.0f}, {RoofType::Gable, 6.0f}, {RoofType::Shed, 12.0f}}) {
        SCOPED_TRACE(roofTypeName(type));
        EXPECT_NEAR(highest(buildRoof(house, kEaves, RoofOptions{type, 45, 0, 0.8f, -1, 0.5f}).mesh), eavesZ + rise,
                    1e-4f);
    }
    // The pyramid's apex over the quad's centroid, as high as the pitch rises from its nearest edge.
    EXPECT_NEAR(highest(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Pyramid, 45, 0, 0.8f, -1, 0.5f}).mesh),
                eavesZ + 6, 1e-4f);
    EXPECT_NEAR(highest(buildRoof(house, kEaves, RoofOptions{RoofType::Flat, 45, 0, 0.8f, -1, 0.5f}).mesh),
                eavesZ + 0.8f, 1e-5f);
}

TEST(RoofShapes, ShedRisesFromTheChosenEdge) {
    RoofResult roof = buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Shed, 45, 0, 0.8f, 1, 0.5f});
    // Edge 1 runs up the east side: the roof rises 20 m westwards.
    for (const Vec3f &p : roof.mesh.positions) {
        if (p.z > kEaves + 1) {
            EXPECT_NEAR(p.z - (kEaves + 1), 20 - p.x, 1e-4f);
        }
    }
    EXPECT_NEAR(highest(roof.mesh), kEaves + 1 + 20, 1e-4f);
}

TEST(RoofShapes, OverhangWidensAndLowersTheEaves) {
    float pitch = 40, overhang = 0.5f;
    RoofFootprint wider{{{-0.5f, -0.5f}, {20.5f, -0.5f}, {20.5f, 12.5f}, {-0.5f, 12.5f}}, {}, 1};
    for (RoofType type : {RoofType::Hip, RoofType::Mansard}) {
        SCOPED_TRACE(roofTypeName(type));
        RoofResult roof = buildRoof(rectangle(), kEaves, RoofOptions{type, pitch, overhang, 0.8f, -1, 0.5f});
        EXPECT_FALSE(roof.fallback.has_value());
        expectRoofOver(roof, wider, 1 + (kEaves - overhang * std::tan(radians(pitch))));
    }
    // Gables and the shed's walls stand flush with the house: those edges do not move. The
    // pyramid's faces over the 10 m reaches are shallower than those over the 6 m ones, so
    // their eaves reach 10/6 as far.
    float lowered = 1 + (kEaves - overhang * std::tan(radians(pitch)));
    RoofFootprint gabled{{{0, -0.5f}, {20, -0.5f}, {20, 12.5f}, {0, 12.5f}}, {}, 1};
    RoofFootprint shed{{{0, -0.5f}, {20, -0.5f}, {20, 12}, {0, 12}}, {}, 1};
    for (auto [type, eaves] :
         {std::pair{RoofType::Gable, gabled}, {RoofType::HalfHip, gabled}, {RoofType::Shed, shed}}) {
        SCOPED_TRACE(roofTypeName(type));
        RoofResult roof = buildRoof(rectangle(), kEaves, RoofOptions{type, pitch, overhang, 0.8f, -1, 0.5f});
        EXPECT_FALSE(roof.fallback.has_value()) << *roof.fallback;
        expectRoofOver(roof, eaves, lowered);
    }
    // Its corners are worked out in floats, not the exact ones a test could write down.
    RoofResult pyramid =
        buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Pyramid, pitch, overhang, 0.8f, -1, 0.5f});
    EXPECT_FALSE(pyramid.fallback.has_value()) << *pyramid.fallback;
    float far = overhang * 10 / 6;
    double covered = 0;
    for (size_t t = 0; t < pyramid.mesh.triangleCount(); ++t) covered += projectedArea(pyramid.mesh, t);
    EXPECT_NEAR(covered, (20 + 2 * far) * 13, 1e-5 * covered);
    for (const Vec3f &p : pyramid.mesh.positions) {
        if (p.z < lowered + 1e-3f) {
            EXPECT_NEAR(p.z, lowered, 1e-4f);
            EXPECT_NEAR(std::abs(p.x - 10), 10 + far, 1e-4f);
            EXPECT_NEAR(std::abs(p.y - 6), 6.5f, 1e-4f);
        }
    }
    RoofResult flat = buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Flat, pitch, overhang, 0.8f, -1, 0.5f});
    expectRoofOver(flat, wider, 1 + kEaves);
}

TEST(RoofShapes, OverhangTheFootprintCannotTakeIsLeftOut) {
    // A slit 1 m wide between the U's arms closes under a 0.6 m overhang on each side.
    RoofFootprint narrow{{{0, 0}, {21, 0}, {21, 20}, {11, 20}, {11, 8}, {10, 8}, {10, 20}, {0, 20}}, {}, 0};
    RoofResult roof = buildRoof(narrow, kEaves, RoofOptions{RoofType::Hip, 40, 0.6f, 0.8f, -1, 0.5f});
    EXPECT_EQ(roof.built, RoofType::Hip);
    ASSERT_TRUE(roof.fallback.has_value());
    EXPECT_NE(roof.fallback->find("overhang"), std::string::npos) << *roof.fallback;
    expectRoofOver(roof, narrow, kEaves);
}

TEST(RoofShapes, RefusesBadArguments) {
    RoofFootprint clockwise = rectangle();
    std::reverse(clockwise.outer.begin(), clockwise.outer.end());
    EXPECT_THROW(buildRoof(clockwise, kEaves, RoofOptions{}), std::invalid_argument);
    RoofFootprint holeOutside = rectangle();
    holeOutside.holes.push_back({{30, 1}, {30, 2}, {31, 2}, {31, 1}});
    EXPECT_THROW(buildRoof(holeOutside, kEaves, RoofOptions{}), std::invalid_argument);
    EXPECT_THROW(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Hip, 90, 0, 0.8f, -1, 0.5f}),
                 std::invalid_argument);
    EXPECT_THROW(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Shed, 30, -1, 0.8f, -1, 0.5f}),
                 std::invalid_argument);
    EXPECT_THROW(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Shed, 30, 0, 0.8f, 4, 0.5f}),
                 std::invalid_argument);
    EXPECT_THROW(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::HalfHip, 30, 0, 0.8f, -1, 1}),
                 std::invalid_argument);
    EXPECT_THROW(buildRoof(rectangle(), kEaves, RoofOptions{RoofType::HalfHip, 30, 0, 0.8f, -1, 0}),
                 std::invalid_argument);
}

// The footprint edges (numbered through the rings) that gable walls stand on, each wall
// triangle vertical and within 0.1 mm of one edge's vertical plane, between its ends.
std::set<size_t> gableWallEdges(const Mesh &m, const RoofFootprint &footprint) {
    std::vector<std::pair<Vec2f, Vec2f>> edges;
    for (const auto &ring : ringsOf(footprint)) {
        for (size_t i = 0; i < ring.size(); ++i) edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
    std::set<size_t> under;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != RoofGableWall) continue;
        EXPECT_NEAR(normalize(crossOf(m, t)).z, 0, 1e-5f) << "triangle " << t;
        auto standsOn = [&](const std::pair<Vec2f, Vec2f> &edge) {
            for (int k = 0; k < 3; ++k) {
                Vec3f p = corner(m, t, k);
                if (distanceToSegment({p.x, p.y}, edge.first, edge.second) > 1e-4) return false;
            }
            return true;
        };
        auto edge = std::find_if(edges.begin(), edges.end(), standsOn);
        EXPECT_NE(edge, edges.end()) << "triangle " << t << " stands on no edge";
        if (edge != edges.end()) under.insert(size_t(edge - edges.begin()));
    }
    return under;
}

TEST(RoofShapes, GableEndsStandOnTheEndsOfRidges) {
    const std::pair<Case, std::set<size_t>> cases[] = {
        {{"quad", quad()}, {1, 3}},
        {{"L", lShape()}, {1, 4}},
        {{"T", tShape()}, {1, 4, 7}},
        {{"U", uShape()}, {2, 6}},
        {{"square", {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}, 0}}, {0, 2}}};
    for (const auto &[c, ends] : cases) {
        for (RoofType type : {RoofType::Gable, RoofType::HalfHip}) {
            SCOPED_TRACE(fmt::format("{} roof on {}", roofTypeName(type), c.name));
            RoofResult roof = buildRoof(c.footprint, kEaves, RoofOptions{type, 35, 0, 0.8f, -1, 0.5f});
            EXPECT_EQ(roof.built, type);
            EXPECT_FALSE(roof.fallback.has_value()) << *roof.fallback;
            EXPECT_EQ(gableWallEdges(roof.mesh, c.footprint), ends);
            expectRoofOver(roof, c.footprint, c.footprint.base + kEaves);
        }
    }
}

std::vector<Point> cornersOf(const Mesh &m) {
    std::set<Point> corners;
    for (const Vec3f &p : m.positions) corners.insert(key(p));
    return {corners.begin(), corners.end()};
}

TEST(RoofShapes, GableOverARectangleIsSeedZerosGable) {
    RoofFootprint house = rectangle();
    RoofResult roof = buildRoof(house, kEaves, RoofOptions{RoofType::Gable, 40, 0, 0.8f, -1, 0.5f});
    // Bilke 2009, §2.4.3: the ridge through the midpoints of the two short sides, 6 m (the half
    // depth) · tan 40° above the eaves; two slopes and two gable triangles, nothing else.
    float eavesZ = house.base + kEaves, ridgeZ = eavesZ + 6 * std::tan(radians(40));
    std::vector<Point> theirs = {{0, 0, eavesZ},  {0, 6, ridgeZ},  {0, 12, eavesZ},
                                 {20, 0, eavesZ}, {20, 6, ridgeZ}, {20, 12, eavesZ}};
    std::vector<Point> ours = cornersOf(roof.mesh);
    ASSERT_EQ(ours.size(), theirs.size());
    for (size_t i = 0; i < ours.size(); ++i) {
        EXPECT_NEAR(std::get<0>(ours[i]), std::get<0>(theirs[i]), 1e-4f);
        EXPECT_NEAR(std::get<1>(ours[i]), std::get<1>(theirs[i]), 1e-4f);
        EXPECT_NEAR(std::get<2>(ours[i]), std::get<2>(theirs[i]), 1e-4f);
    }
    EXPECT_EQ(planarFaces(roof.mesh), 4u);
}

bool hasCorner(const Mesh &m, const Vec3f &p) {
    return std::any_of(m.positions.begin(), m.positions.end(), [&](const Vec3f &q) { return length(q - p) < 1e-4f; });
}

TEST(RoofShapes, HalfHipWallsStopAtTheFraction) {
    // 12 m deep at 45°: the ridge 6 m up. A quarter of that, 1.5 m, is wall; the small hips rise
    // from there at 45° and meet the ridge 4.5 m in from the ends.
    RoofResult roof = buildRoof(rectangle(), kEaves, RoofOptions{RoofType::HalfHip, 45, 0, 0.8f, -1, 0.25f});
    float eavesZ = 1 + kEaves, wallTop = -INFINITY;
    for (size_t t = 0; t < roof.mesh.triangleCount(); ++t) {
        if (roof.mesh.triangleMaterials[t] != RoofGableWall) continue;
        for (int k = 0; k < 3; ++k) wallTop = std::max(wallTop, corner(roof.mesh, t, k).z);
    }
    EXPECT_NEAR(wallTop, eavesZ + 1.5f, 1e-4f);
    EXPECT_NEAR(highest(roof.mesh), eavesZ + 6, 1e-4f);
    EXPECT_TRUE(hasCorner(roof.mesh, {4.5f, 6, eavesZ + 6}));
    EXPECT_TRUE(hasCorner(roof.mesh, {15.5f, 6, eavesZ + 6}));
    EXPECT_EQ(gableWallEdges(roof.mesh, rectangle()), (std::set<size_t>{1, 3}));
}

TEST(RoofShapes, GableOnlyOnTheChosenEdge) {
    RoofResult one = buildRoof(rectangle(), kEaves, RoofOptions{RoofType::Gable, 35, 0, 0.8f, 3, 0.5f});
    EXPECT_EQ(one.built, RoofType::Gable);
    EXPECT_FALSE(one.fallback.has_value());
    EXPECT_EQ(gableWallEdges(one.mesh, rectangle()), std::set<size_t>{3});
    // A long side ends no ridge: the roof stays hipped and says why.
    RoofResult side = buildRoof(rectangle(), kEaves, RoofOptions{RoofType::HalfHip, 35, 0, 0.8f, 0, 0.5f});
    EXPECT_EQ(side.built, RoofType::Hip);
    ASSERT_TRUE(side.fallback.has_value());
    EXPECT_NE(side.fallback->find("edge 0"), std::string::npos) << *side.fallback;
}

TEST(RoofShapes, TypesByName) {
    for (RoofType type : kRoofTypes) EXPECT_EQ(roofTypeFromName(roofTypeName(type)), type);
    EXPECT_EQ(roofTypeFromName("Half-Hip"), RoofType::HalfHip);
    EXPECT_EQ(roofTypeFromName("HALFHIP"), RoofType::HalfHip);
    EXPECT_EQ(roofTypeFromName("Gable"), RoofType::Gable);
    EXPECT_EQ(roofTypeFromName("gambrel"), std::nullopt);
    EXPECT_EQ(roofTypeFromName(""), std::nullopt);
}

float unit(uint32_t polygon, uint32_t draw) { return bitsToUnitFloat(hashValues({0x5eed, polygon, draw})); }

// A star-shaped polygon round the origin, 5–20 points at radii 5–20 m, every third with a
// clockwise star-shaped courtyard of radius ≤ 1.5 m, well inside the 2 m the outline clears.
RoofFootprint randomFootprint(uint32_t id) {
    RoofFootprint footprint;
    uint32_t draw = 0;
    auto star = [&](size_t points, float minRadius, float maxRadius) {
        std::vector<Vec2f> ring;
        for (size_t i = 0; i < points; ++i) {
            float angle = 2 * kPi * (float(i) + 0.8f * unit(id, draw++)) / float(points);
            float radius = minRadius + (maxRadius - minRadius) * unit(id, draw++);
            ring.push_back({radius * std::cos(angle), radius * std::sin(angle)});
        }
        return ring;
    };
    footprint.outer = star(5 + size_t(16 * unit(id, draw++)), 5, 20);
    if (id % 3 == 0) {
        std::vector<Vec2f> hole = star(4 + size_t(4 * unit(id, draw++)), 0.5f, 1.5f);
        std::reverse(hole.begin(), hole.end());
        footprint.holes.push_back(hole);
    }
    return footprint;
}

// Every footprint gets a flat roof and one sloped type in turn (a gable or half-hip that cannot
// be built falls back through the hip), which keeps the `roofs` label within seconds.
TEST(RoofShapes, RandomFootprintsAlwaysGetARoof) {
    constexpr uint32_t kFootprints = 10000;
    const RoofType sloped[] = {RoofType::Hip, RoofType::Gable, RoofType::HalfHip};
    std::map<RoofType, int> fallbacks;
    for (uint32_t id = 0; id < kFootprints; ++id) {
        RoofFootprint footprint = randomFootprint(id);
        for (RoofType type : {sloped[size_t(3 * unit(id, 0xca7))], RoofType::Flat}) {
            RoofResult roof = buildRoof(footprint, kEaves, RoofOptions{type, 35, 0.3f, 0.8f, -1, 0.5f});
            ASSERT_GT(roof.mesh.triangleCount(), 0u) << "footprint " << id;
            if (roof.built != type) {
                ++fallbacks[type];
                ASSERT_TRUE(roof.fallback.has_value() && !roof.fallback->empty()) << "footprint " << id;
            }
        }
    }
    for (RoofType type : sloped) RecordProperty(fmt::format("{}_fallbacks", roofTypeName(type)), fallbacks[type]);
}

}  // namespace
}  // namespace veduta
