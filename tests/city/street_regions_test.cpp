// Street surfaces tile by tile: the tiles' regions together are the whole network's union, the
// same point set, on the test cities, grown towns and random networks; their kerbs are its
// boundary once; the mesh is the same on any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <CGAL/Boolean_set_operations_2.h>
#include <tbb/global_control.h>

#include "city/city_data.h"
#include "city/generate_city.h"
#include "city/grown_city.h"
#include "city/osm_import.h"
#include "city/street_geometry.h"
#include "city/street_regions.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

// The union of every tile's regions.
struct Joined {
    StreetPolygonSet carriageway, between, junctions, sidewalks;
    std::vector<StreetSegment> kerbs;
};

Joined joinedTiles(const StreetNetwork &network, size_t piecesPerTile, size_t *tileCount = nullptr) {
    StreetTiling tiling = streetTiling(network, {}, piecesPerTile);
    if (tileCount) *tileCount = tiling.tiles.size();
    Joined all;
    for (size_t t = 0; t < tiling.tiles.size(); ++t) {
        StreetTileRegions tile = streetTileRegions(tiling, t);
        all.carriageway.join(tile.carriageway);
        all.between.join(tile.between);
        all.junctions.join(tile.junctions);
        all.sidewalks.join(tile.sidewalks);
        all.kerbs.insert(all.kerbs.end(), tile.kerbs.begin(), tile.kerbs.end());
    }
    return all;
}

bool same(StreetPolygonSet a, const StreetPolygonSet &b) {
    a.symmetric_difference(b);
    return a.is_empty();
}

double boundaryLength(const std::vector<StreetSegment> &segments) {
    double sum = 0;
    for (const StreetSegment &s : segments) sum += std::sqrt(CGAL::to_double(s.squared_length()));
    return sum;
}

// Tiles of at most `piecesPerTile` pieces against one tile of the whole network: the same
// regions exactly, and kerbs that lie on the carriageway's boundary, the road on their left,
// as long as it all.
void expectSameAsOneUnion(const StreetNetwork &network, size_t piecesPerTile) {
    size_t tiles = 0;
    Joined whole = joinedTiles(network, std::numeric_limits<size_t>::max());
    Joined tiled = joinedTiles(network, piecesPerTile, &tiles);
    EXPECT_GT(tiles, 1u) << "the network is one tile: nothing compared";
    EXPECT_TRUE(same(tiled.carriageway, whole.carriageway));
    EXPECT_TRUE(same(tiled.between, whole.between));
    EXPECT_TRUE(same(tiled.junctions, whole.junctions));
    EXPECT_TRUE(same(tiled.sidewalks, whole.sidewalks));
    for (const StreetSegment &kerb : tiled.kerbs) {
        StreetPoint middle = CGAL::midpoint(kerb.source(), kerb.target());
        ASSERT_EQ(whole.carriageway.oriented_side(middle), CGAL::ON_ORIENTED_BOUNDARY);
        // A centimetre to the left lies on the road (the segments are at least that long here).
        StreetKernel::Vector_2 along = kerb.to_vector();
        double length = std::sqrt(CGAL::to_double(along.squared_length()));
        if (length < 0.1) continue;
        StreetKernel::Vector_2 left(-along.y() * 0.01 / length, along.x() * 0.01 / length);
        EXPECT_EQ(whole.carriageway.oriented_side(middle + left), CGAL::ON_POSITIVE_SIDE);
    }
    double wholeLength = boundaryLength(whole.kerbs);
    EXPECT_NEAR(boundaryLength(tiled.kerbs), wholeLength, 1e-9 * wholeLength);
}

StreetNetwork cityFile(const char *name) { return streetNetworkOf(readCityData(test::sourceFile(name))); }

StreetNetwork osmFile(const char *name) { return streetNetworkOf(importOsm(test::sourceFile(name), {})); }

StreetNetwork grownTown(const char *rules, uint32_t seed, float radius) {
    CityGrowth growth;
    growth.radius = radius;
    growth.seed = seed;
    std::vector<std::string> warnings;
    return streetNetworkOf(growCity(
        readStreetRuleFile(test::sourceFile(std::string("rules/streets/") + rules + ".txt")), growth, warnings));
}

TEST(StreetRegions, TilesOfTheTestCitiesAreTheirWholeUnion) {
    {
        SCOPED_TRACE("gruenderzeit-district");
        expectSameAsOneUnion(cityFile("cities/gruenderzeit-district.xml"), 12);
    }
    {
        SCOPED_TRACE("bilke-listing-2-1");
        expectSameAsOneUnion(cityFile("cities/bilke-listing-2-1.xml"), 12);
    }
    {
        SCOPED_TRACE("hillside town");
        expectSameAsOneUnion(osmFile("data/hillside/town.osm"), 24);
    }
    for (const char *regression : {"fuzz/regressions/osm/degenerate_bevel_triangle.osm",
                                   "fuzz/regressions/osm/difference_face_of_two_outer_boundaries.osm"}) {
        SCOPED_TRACE(regression);
        expectSameAsOneUnion(osmFile(regression), 16);
    }
}

TEST(StreetRegions, TilesOfSeededTownsAreTheirWholeUnion) {
    for (const char *rules : {"grid", "organic", "radial"}) {
        for (uint32_t seed : {3u, 11u}) {
            SCOPED_TRACE(std::string(rules) + " " + std::to_string(seed));
            expectSameAsOneUnion(grownTown(rules, seed, 160), 48);
        }
    }
}

// Random crossing streets of random widths: overlaps at every angle, cut by the tiles anywhere.
TEST(StreetRegions, TilesOfRandomNetworksAreTheirWholeUnion) {
    std::mt19937 random(29);
    std::uniform_real_distribution<float> coordinate(0, 300), width(2, 20);
    for (int n = 0; n < 8; ++n) {
        StreetNetwork network;
        for (int k = 0; k < 16; ++k) network.nodes.push_back({coordinate(random), coordinate(random)});
        for (uint32_t k = 0; k + 1 < 16; ++k) network.streets.push_back({k, uint32_t(random() % 16), width(random)});
        SCOPED_TRACE(n);
        expectSameAsOneUnion(network, 8);
    }
}

// A grid laid out so that the first splits fall on street edges: the extent runs from the
// joints at -72 and 80 on either axis, the same reach beyond each, so that its middle is 4, the
// edge of the 8 m streets along x = 0 and y = 0. There the tiles' edges are kerbs.
TEST(StreetRegions, TileEdgesAlongStreetEdgesKeepTheRegionAndItsKerbs) {
    const float at[] = {-72, -36, 0, 40, 80};
    StreetNetwork network;
    auto node = [&](int x, int y) { return uint32_t(y * 5 + x); };
    for (float y : at)
        for (float x : at) network.nodes.push_back({x, y});
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) {
            if (x < 4) network.streets.push_back({node(x, y), node(x + 1, y), 8});
            if (y < 4) network.streets.push_back({node(x, y), node(x, y + 1), 8});
        }
    StreetTiling tiling = streetTiling(network, {}, 8);
    ASSERT_GT(tiling.tiles.size(), 2u);
    auto splitAt4 = [&](auto edge) {
        return std::any_of(tiling.tiles.begin(), tiling.tiles.end(), [&](const BoxTile &t) { return edge(t.box); });
    };
    EXPECT_TRUE(splitAt4([](const Box2d &b) { return b.highX == 4; }));
    EXPECT_TRUE(splitAt4([](const Box2d &b) { return b.highY == 4; }));
    expectSameAsOneUnion(network, 8);
}

float area(const Mesh &m, StreetSurface surface) {
    double sum = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        if (m.triangleMaterials[t] != surface) continue;
        const Vec3f &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
                    &c = m.positions[m.indices[3 * t + 2]];
        sum += 0.5 * length(cross(b - a, c - a));
    }
    return float(sum);
}

// The meshes of many tiles and of one cover the same areas, surface by surface.
TEST(StreetRegions, TiledMeshesCoverWhatOneUnionCovers) {
    StreetNetwork network = grownTown("grid", 5, 300);
    Mesh whole = streetGeometry(network, {}, std::numeric_limits<size_t>::max());
    Mesh tiled = streetGeometry(network, {}, 32);
    EXPECT_GT(tiled.triangleCount(), whole.triangleCount());  // cut along the tiles' edges
    for (StreetSurface surface : {StreetCarriageway, StreetJunction, StreetSidewalk, StreetKerb}) {
        SCOPED_TRACE(surface);
        float expected = area(whole, surface);
        EXPECT_GT(expected, 0);
        EXPECT_NEAR(area(tiled, surface), expected, 1e-4f * expected);
    }
    for (uint32_t i : tiled.indices) ASSERT_LT(i, tiled.positions.size());
    EXPECT_EQ(tiled.triangleMaterials.size(), tiled.triangleCount());
}

// The tiles are worked out on all cores and joined in their order.
TEST(StreetRegions, TheMeshIsTheSameOnAnyNumberOfThreads) {
    StreetNetwork network = grownTown("organic", 7, 300);
    auto builtOn = [&](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return streetGeometry(network, {}, 32);
    };
    Mesh one = builtOn(1), four = builtOn(4);
    EXPECT_GT(one.triangleCount(), 0u);
    EXPECT_EQ(one.positions.size(), four.positions.size());
    EXPECT_TRUE(one.positions == four.positions);
    EXPECT_TRUE(one.normals == four.normals);
    ASSERT_EQ(one.uvs.size(), four.uvs.size());
    for (size_t i = 0; i < one.uvs.size(); ++i)
        ASSERT_TRUE(one.uvs[i].x == four.uvs[i].x && one.uvs[i].y == four.uvs[i].y) << i;
    EXPECT_EQ(one.indices, four.indices);
    EXPECT_EQ(one.triangleMaterials, four.triangleMaterials);
}

}  // namespace
}  // namespace veduta
