#include "streets/street_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "streets/fixed_draws.h"
#include "streets/grown_streets.h"
#include "streets/listing_4_2.h"
#include "streets/street_rule_file.h"

namespace veduta {
namespace {

using test::kListing42;

using test::FixedDraws;
using test::kSquareGridDraw;

using Town = test::GrownStreets;

TEST(StreetBuilderListing42, TheBranchOf53EndsOn76AndClosesTheThesisCycle) {
    FixedDraws draws(kSquareGridDraw);
    Town town(kListing42, draws);
    town.grow(1e6f, 13);
    const StreetBuilder &streets = town.streets;
    // Tab. 4.6.1's cycle edge 46-76: S 53's F is bent onto node 76 (NN, distance 0).
    VertexId v46 = streets.vertexOf(46), v76 = streets.vertexOf(76);
    ASSERT_NE(v46, kNoVertex);
    ASSERT_NE(v76, kNoVertex);
    EXPECT_NE(streets.graph().edgeBetween(v46, v76), UINT32_MAX);
    EXPECT_GE(streets.counts().snapped, 1u);
    EXPECT_EQ(streets.counts().refused, 0u);
    test::expectSoundNetwork(streets.graph());
}

TEST(StreetBuilderListing42, ASquareGridHasAVertexWhereverStreetsMeet) {
    FixedDraws draws(kSquareGridDraw);
    Town town(kListing42, draws);
    town.grow(45);
    const StreetGraph &graph = town.streets.graph();
    test::expectSoundNetwork(graph);
    // Every vertex on the lattice of 10, none twice.
    std::set<std::pair<long, long>> seen;
    for (const StreetVertex &v : graph.vertices()) {
        EXPECT_NEAR(v.position.x, std::round(v.position.x / 10) * 10, 1e-3f);
        EXPECT_NEAR(v.position.y, std::round(v.position.y / 10) * 10, 1e-3f);
        EXPECT_TRUE(seen.emplace(std::lround(v.position.x), std::lround(v.position.y)).second)
            << v.position.x << ", " << v.position.y;
    }
    EXPECT_GT(graph.edges().size(), graph.vertices().size());  // cycles: blocks
}

TEST(StreetBuilderProperties, JitteredGridsOfManySeedsAreSound) {
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE(seed);
        SeededDraws draws(seed);
        Town town(kListing42, draws);
        EXPECT_EQ(town.grow(60).stop, GrowthStop::Exhausted);
        test::expectSoundNetwork(town.streets.graph());
        const StreetCounts &counts = town.streets.counts();
        EXPECT_GT(counts.snapped + counts.split, 10u);
        EXPECT_GT(town.streets.graph().edges().size(), town.streets.graph().vertices().size());
    }
}

std::vector<std::tuple<float, float, float>> positions(const StreetGraph &graph) {
    std::vector<std::tuple<float, float, float>> list;
    for (const StreetVertex &v : graph.vertices()) list.emplace_back(v.position.x, v.position.y, v.position.z);
    return list;
}

std::vector<std::pair<VertexId, VertexId>> ends(const StreetGraph &graph) {
    std::vector<std::pair<VertexId, VertexId>> list;
    for (const StreetEdge &e : graph.edges()) list.emplace_back(e.a, e.b);
    return list;
}

TEST(StreetBuilderProperties, TheSameSeedGrowsTheSameGraph) {
    SeededDraws draws(7), same(7), other(8);
    Town a(kListing42, draws), b(kListing42, same), c(kListing42, other);
    a.grow(50);
    b.grow(50);
    c.grow(50);
    EXPECT_EQ(positions(a.streets.graph()), positions(b.streets.graph()));
    EXPECT_EQ(ends(a.streets.graph()), ends(b.streets.graph()));
    EXPECT_NE(positions(a.streets.graph()), positions(c.streets.graph()));
}

TEST(StreetBuilder, ARefusedStreetCutsOffWhatWouldGrowFromIt) {
    FixedDraws draws(kSquareGridDraw);
    // Each A draws a street of 10 and a branch of 2, too short to be built.
    Town town("o: A\np: A -> F(10)[&(90)F(2)A]A\n", draws);
    town.grow(35);
    const StreetCounts &counts = town.streets.counts();
    EXPECT_EQ(counts.proposed, 4u);  // from x = 0, 10, 20, 30
    EXPECT_EQ(counts.refused, 4u);
    EXPECT_EQ(town.streets.graph().vertices().size(), 5u);
    EXPECT_EQ(town.streets.graph().edges().size(), 4u);
    EXPECT_EQ(town.growth.pendingCount(), 1u);  // the A at x = 40 waits outside; the branches' A are gone
}

TEST(StreetBuilder, AStreetMetIsCutAndWhatLiesBeyondIsCutOff) {
    FixedDraws draws(kSquareGridDraw);
    // A street north along x = 5, then one east from the origin that crosses it and goes on.
    Town town("o: R[f(5)&(90)f(5)&(180)F(10)]F(10)A\np: A -> F(10)\n", draws);
    town.grow(100);
    const StreetBuilder &streets = town.streets;
    EXPECT_EQ(streets.counts().split, 1u);
    EXPECT_EQ(streets.counts().proposed, 1u);   // the street north
    EXPECT_EQ(town.growth.pendingCount(), 0u);  // the A beyond the crossing is cut off
    const StreetGraph &graph = streets.graph();
    ASSERT_EQ(graph.vertices().size(), 4u);  // the origin, the street's two ends, the crossing
    EXPECT_EQ(graph.edges().size(), 3u);
    EXPECT_TRUE(graph.vertex(3).isStatic);
    EXPECT_NEAR(graph.vertex(3).position.x, 5, 1e-5f);
    EXPECT_NEAR(graph.vertex(3).position.y, 0, 1e-5f);
}

// Ground no street may cross east of x = 200 (as water would be).
struct WaterEastOf final : StreetEnvironment {
    float shore = 200;
    float freeLength(const Vec3f &start, const Vec3f &direction, float length) const override {
        if (direction.x <= 0 || start.x + direction.x * length <= shore) return length;
        return std::max(0.0f, (shore - start.x) / direction.x);
    }
};

TEST(StreetBuilder, TheGroundStopsEveryStreetAsAStreetMetWould) {
    WaterEastOf water;
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        SeededDraws draws(seed);
        Town town(test::patternText("grid"), draws, &water);
        EXPECT_EQ(town.grow(500).stop, GrowthStop::Exhausted);
        const StreetGraph &graph = town.streets.graph();
        size_t onTheShore = 0;
        for (const StreetVertex &v : graph.vertices()) {
            EXPECT_LE(v.position.x, water.shore + 1e-3f);
            onTheShore += std::abs(v.position.x - water.shore) < 1e-3f;
        }
        EXPECT_GT(town.streets.counts().stopped, 3u);
        EXPECT_GE(onTheShore, town.streets.counts().stopped);
        test::expectSoundNetwork(graph);
    }
}

}  // namespace
}  // namespace veduta

namespace veduta {
namespace {

double distanceToSegmentForTest(Vec2f p, Vec2f a, Vec2f b) {
    Vec2f ab = b - a, ap = p - a;
    double t = std::clamp(double(dot(ap, ab)) / double(dot(ab, ab)), 0.0, 1.0);
    double x = a.x + t * ab.x - p.x, y = a.y + t * ab.y - p.y;
    return std::sqrt(x * x + y * y);
}

// A road already there (CityGrowth::roads), a slanted line through the window with a bend: the
// grid's streets meet it as any street, ending on it or cutting it, and it stays static.
TEST(StreetBuilder, ARoadAlreadyThereIsMetByTheStreetsThatGrowOntoIt) {
    std::vector<std::vector<Vec2f>> roads{{{-400, -150}, {0, 130}, {400, 200}}};
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        SeededDraws draws(seed);
        StreetRuleSet rules = parseStreetRules(test::patternText("grid"), "grid.txt");
        WordGraph words(rules.initialWord);
        StreetBuilder streets(words, {}, nullptr, roads);
        StreetGrowth growth(words, rules.rules, streets.nodeQuery(), draws, &streets);
        EXPECT_EQ(growth.grow({{0, 0}, 350}, {}).stop, GrowthStop::Exhausted);
        const StreetGraph &graph = streets.graph();
        // The road's three points, static, and each street that met it split it or ended on it.
        for (VertexId v : {1u, 2u, 3u}) EXPECT_TRUE(graph.vertex(v).isStatic);
        EXPECT_EQ(graph.vertex(2).position, (Vec3f{0, 130, 0}));
        EXPECT_GT(streets.counts().split + streets.counts().snapped, 5u);
        // Every vertex on the road lies on one of its two pieces, and some streets meet it there.
        size_t onTheRoad = 0;
        for (const StreetVertex &v : graph.vertices()) {
            Vec2f p{v.position.x, v.position.y};
            double d = std::min(distanceToSegmentForTest(p, roads[0][0], roads[0][1]),
                                distanceToSegmentForTest(p, roads[0][1], roads[0][2]));
            onTheRoad += d < 1e-3 && v.edges.size() >= 3;
        }
        EXPECT_GT(onTheRoad, 3u);
        test::expectSoundNetwork(graph);
    }
}

}  // namespace
}  // namespace veduta
