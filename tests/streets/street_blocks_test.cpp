#include "streets/street_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <ostream>
#include <random>
#include <set>
#include <stdexcept>

namespace veduta {

void PrintTo(const StreetBlock &block, std::ostream *out) {
    auto print = [&](const std::vector<uint32_t> &cycle) {
        *out << "(";
        for (uint32_t i : cycle) *out << " " << i;
        *out << " )";
    };
    *out << "boundary ";
    print(block.boundary);
    for (const std::vector<uint32_t> &hole : block.holes) {
        *out << " hole ";
        print(hole);
    }
    *out << " area " << block.area;
}

namespace {

using Ring = std::vector<uint32_t>;

struct Graph {
    std::vector<PlanarPoint> points;
    std::vector<PlanarEdge> edges;

    void addRing(const Ring &ring) {
        for (size_t i = 0; i < ring.size(); ++i) edges.emplace_back(ring[i], ring[(i + 1) % ring.size()]);
    }
};

// ---- Independent plain-double geometry for the checks ----

double cross(const PlanarPoint &o, const PlanarPoint &a, const PlanarPoint &b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

double twiceArea(const std::vector<PlanarPoint> &points, const Ring &ring) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const PlanarPoint &a = points[ring[i]], &b = points[ring[(i + 1) % ring.size()]];
        sum += a.x * b.y - a.y * b.x;
    }
    return sum;
}

bool onSegment(const PlanarPoint &a, const PlanarPoint &b, const PlanarPoint &p) {
    return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
        p.y <= std::max(a.y, b.y);
}

bool segmentsMeet(const PlanarPoint &a, const PlanarPoint &b, const PlanarPoint &c, const PlanarPoint &d) {
    double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return onSegment(c, d, a) || onSegment(c, d, b) || onSegment(a, b, c) || onSegment(a, b, d);
}

bool inRing(const std::vector<PlanarPoint> &points, const Ring &ring, const PlanarPoint &p) {
    bool inside = false;
    for (size_t i = 0; i < ring.size(); ++i) {
        const PlanarPoint &a = points[ring[i]], &b = points[ring[(i + 1) % ring.size()]];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

bool inBlock(const std::vector<PlanarPoint> &points, const StreetBlock &block, const PlanarPoint &p) {
    if (!inRing(points, block.boundary, p)) return false;
    return std::ranges::none_of(block.holes, [&](const Ring &hole) { return inRing(points, hole, p); });
}

// A point just inside the block, beside the middle of its first boundary edge (the block lies to
// the left of its counter-clockwise boundary).
PlanarPoint pointInside(const std::vector<PlanarPoint> &points, const StreetBlock &block) {
    const PlanarPoint &a = points[block.boundary[0]], &b = points[block.boundary[1]];
    double dx = b.x - a.x, dy = b.y - a.y, step = 1e-4;
    return {(a.x + b.x) / 2 - dy * step, (a.y + b.y) / 2 + dx * step};
}

// The ring is a simple polygon: three points or more, none twice, edges meeting only where they
// follow each other, and running the way `sign` says (+1 counter-clockwise).
void expectSimple(const std::vector<PlanarPoint> &points, const Ring &ring, int sign) {
    ASSERT_GE(ring.size(), 3u);
    EXPECT_EQ(std::set<uint32_t>(ring.begin(), ring.end()).size(), ring.size());
    size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
        const PlanarPoint &a = points[ring[i]], &b = points[ring[(i + 1) % n]], &c = points[ring[(i + 2) % n]];
        EXPECT_FALSE(onSegment(a, b, c) || onSegment(b, c, a)) << "edges fold back at " << ring[(i + 1) % n];
        for (size_t j = i + 2; j < n; ++j) {
            if ((j + 1) % n == i) continue;
            EXPECT_FALSE(segmentsMeet(a, b, points[ring[j]], points[ring[(j + 1) % n]]))
                << "edges from " << ring[i] << " and " << ring[j] << " meet";
        }
    }
    EXPECT_GT(sign * twiceArea(points, ring), 0);
}

// Every block a simple polygon with simple, disjoint holes and its area, no two sharing an edge
// the same way round, and a point inside each lying in no other.
void expectSound(const std::vector<PlanarPoint> &points, const std::vector<StreetBlock> &blocks) {
    std::set<std::pair<uint32_t, uint32_t>> directedEdges;
    for (const StreetBlock &block : blocks) {
        expectSimple(points, block.boundary, 1);
        std::set<uint32_t> used(block.boundary.begin(), block.boundary.end());
        double twice = twiceArea(points, block.boundary);
        for (const Ring &hole : block.holes) {
            expectSimple(points, hole, -1);
            for (uint32_t i : hole) EXPECT_TRUE(used.insert(i).second) << "point " << i << " twice in a block";
            twice += twiceArea(points, hole);
        }
        EXPECT_NEAR(block.area, twice / 2, 1e-12 * std::abs(twice));
        EXPECT_GT(block.area, 0);
        std::vector<Ring> rings{block.boundary};
        rings.insert(rings.end(), block.holes.begin(), block.holes.end());
        for (const Ring &ring : rings) {
            for (size_t i = 0; i < ring.size(); ++i) {
                EXPECT_TRUE(directedEdges.emplace(ring[i], ring[(i + 1) % ring.size()]).second)
                    << "edge " << ring[i] << "-" << ring[(i + 1) % ring.size()] << " twice the same way round";
            }
        }
    }
    for (size_t b = 0; b < blocks.size(); ++b) {
        PlanarPoint p = pointInside(points, blocks[b]);
        EXPECT_TRUE(inBlock(points, blocks[b], p));
        for (size_t other = 0; other < blocks.size(); ++other) {
            if (other == b) continue;
            EXPECT_FALSE(inBlock(points, blocks[other], p)) << "blocks " << b << ", " << other;
        }
    }
}

// Both methods on one graph: equal, and the arrangement seeing no crossing.
BlockResult bothWays(const Graph &graph) {
    BlockResult arrangement = blocksByArrangement(graph.points, graph.edges);
    BlockResult walk = blocksByFaceWalk(graph.points, graph.edges);
    EXPECT_EQ(arrangement.blocks, walk.blocks);
    EXPECT_EQ(arrangement.nonSimpleFaces, walk.nonSimpleFaces);
    EXPECT_EQ(arrangement.ignoredEdges, walk.ignoredEdges);
    EXPECT_EQ(arrangement.ignoredPoints, walk.ignoredPoints);
    EXPECT_EQ(arrangement.unmatchedEdges, 0u);
    EXPECT_EQ(arrangement.invalidFaces, 0u);
    return arrangement;
}

// The same, and the blocks sound.
BlockResult blocksOf(const Graph &graph) {
    BlockResult result = bothWays(graph);
    expectSound(graph.points, result.blocks);
    return result;
}

Graph square() {
    Graph graph{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
    graph.addRing({0, 1, 2, 3});
    return graph;
}

TEST(StreetBlocks, ASquareIsOneBlock) {
    BlockResult result = blocksOf(square());
    ASSERT_EQ(result.blocks.size(), 1u);
    EXPECT_EQ(result.blocks[0], (StreetBlock{{0, 1, 2, 3}, {}, 1.0}));
    EXPECT_EQ(result.nonSimpleFaces, 0u);
    EXPECT_EQ(result.ignoredEdges, 0u);
    EXPECT_EQ(result.ignoredPoints, 0u);
}

TEST(StreetBlocks, TheBoundaryStartsAtItsSmallestIndexCounterClockwise) {
    // The same square, its points numbered clockwise from another corner.
    Graph graph{{{1, 1}, {1, 0}, {0, 0}, {0, 1}}, {}};
    graph.addRing({3, 2, 1, 0});
    BlockResult result = blocksOf(graph);
    ASSERT_EQ(result.blocks.size(), 1u);
    EXPECT_EQ(result.blocks[0].boundary, (Ring{0, 3, 2, 1}));
}

TEST(StreetBlocks, AGridOfThreeByThreeSquaresHasNineBlocks) {
    Graph graph;
    auto at = [](uint32_t i, uint32_t j) { return j * 4 + i; };
    for (uint32_t j = 0; j < 4; ++j) {
        for (uint32_t i = 0; i < 4; ++i) graph.points.push_back({10.0 * i, 10.0 * j});
    }
    for (uint32_t j = 0; j < 4; ++j) {
        for (uint32_t i = 0; i < 4; ++i) {
            if (i < 3) graph.edges.emplace_back(at(i, j), at(i + 1, j));
            if (j < 3) graph.edges.emplace_back(at(i, j), at(i, j + 1));
        }
    }
    BlockResult result = blocksOf(graph);
    ASSERT_EQ(result.blocks.size(), 9u);
    for (uint32_t j = 0; j < 3; ++j) {
        for (uint32_t i = 0; i < 3; ++i) {
            StreetBlock cell{{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, {}, 100.0};
            EXPECT_NE(std::ranges::find(result.blocks, cell), result.blocks.end()) << "cell " << i << ", " << j;
        }
    }
}

TEST(StreetBlocks, DeadEndsInsideAndOutsideAreLeftOut) {
    Graph graph{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 0}, {2, 2}, {1, 3}, {3, 2}, {6, 4}, {7, 5}}, {}};
    graph.addRing({0, 4, 1, 2, 3});
    // Inside: a street from the boundary forking twice; outside: a street hanging off a corner.
    graph.edges.insert(graph.edges.end(), {{4, 5}, {5, 6}, {5, 7}, {2, 8}, {8, 9}});
    BlockResult result = blocksOf(graph);
    ASSERT_EQ(result.blocks.size(), 1u);
    EXPECT_EQ(result.blocks[0], (StreetBlock{{0, 4, 1, 2, 3}, {}, 16.0}));
}

TEST(StreetBlocks, TwoSquaresSharingAnEdgeAreTwoBlocksNotTheirOutline) {
    Graph graph{{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}}, {}};
    graph.addRing({0, 1, 2, 3, 4, 5});
    graph.edges.emplace_back(1, 4);
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{0, 1, 4, 5}, {}, 1.0}, {{1, 2, 3, 4}, {}, 1.0}}));
}

TEST(StreetBlocks, AnIsolatedLoopInsideIsAHoleAndABlockOfItsOwn) {
    Graph graph{{{0, 0}, {6, 0}, {6, 6}, {0, 6}, {2, 2}, {4, 2}, {4, 4}, {2, 4}}, {}};
    graph.addRing({0, 1, 2, 3});
    graph.addRing({4, 5, 6, 7});
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{0, 1, 2, 3}, {{4, 7, 6, 5}}, 32.0}, {{4, 5, 6, 7}, {}, 4.0}}));
}

TEST(StreetBlocks, TwoLoopsJoinedByAStreetInsideAreTwoHoles) {
    Graph graph{{{0, 0}, {10, 0}, {10, 6}, {0, 6}, {1, 2}, {3, 2}, {3, 4}, {1, 4}, {7, 2}, {9, 2}, {9, 4}, {7, 4}}, {}};
    graph.addRing({0, 1, 2, 3});
    graph.addRing({4, 5, 6, 7});
    graph.addRing({8, 9, 10, 11});
    graph.edges.emplace_back(5, 11);  // the bridge between them, left out
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(
        result.blocks,
        (std::vector<StreetBlock>{
            {{0, 1, 2, 3}, {{4, 7, 6, 5}, {8, 11, 10, 9}}, 60 - 8}, {{4, 5, 6, 7}, {}, 4}, {{8, 9, 10, 11}, {}, 4}}));
}

TEST(StreetBlocks, LoopsInsideALoopInsideABlockGoToTheInnermostBlock) {
    // Three nested squares, and two small ones side by side in the middle one: the holes belong
    // to the smallest block around them.
    Graph graph{{{0, 0},
                 {12, 0},
                 {12, 12},
                 {0, 12},
                 {2, 2},
                 {10, 2},
                 {10, 10},
                 {2, 10},
                 {3, 3},
                 {5, 3},
                 {5, 5},
                 {3, 5},
                 {7, 3},
                 {9, 3},
                 {9, 5},
                 {7, 5},
                 {0.5, 6},
                 {1.5, 6},
                 {1, 7}},
                {}};
    graph.addRing({0, 1, 2, 3});
    graph.addRing({4, 5, 6, 7});
    graph.addRing({8, 9, 10, 11});
    graph.addRing({12, 13, 14, 15});
    graph.addRing({16, 17, 18});  // a triangle between the outer two
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks,
              (std::vector<StreetBlock>{{{0, 1, 2, 3}, {{4, 7, 6, 5}, {16, 18, 17}}, 144 - 64 - 0.5},
                                        {{4, 5, 6, 7}, {{8, 11, 10, 9}, {12, 15, 14, 13}}, 64 - 8},
                                        {{8, 9, 10, 11}, {}, 4},
                                        {{12, 13, 14, 15}, {}, 4},
                                        {{16, 17, 18}, {}, 0.5}}));
}

TEST(StreetBlocks, ACollinearPointStaysInTheBoundary) {
    Graph graph{{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}, {}};
    graph.addRing({0, 1, 2, 3, 4});
    BlockResult result = blocksOf(graph);
    ASSERT_EQ(result.blocks.size(), 1u);
    EXPECT_EQ(result.blocks[0], (StreetBlock{{0, 1, 2, 3, 4}, {}, 2.0}));
}

TEST(StreetBlocks, ATreeHasNoBlocks) {
    Graph graph{{{0, 0}, {1, 0}, {2, 0}, {1, 1}, {1, -1}, {3, 1}}, {{0, 1}, {1, 2}, {1, 3}, {1, 4}, {2, 5}}};
    BlockResult result = blocksOf(graph);
    EXPECT_TRUE(result.blocks.empty());
    EXPECT_EQ(result.nonSimpleFaces, 0u);
    EXPECT_TRUE(blocksOf({}).blocks.empty());
}

TEST(StreetBlocks, DuplicateAndZeroLengthEdgesAndStrayPointsAreCounted) {
    Graph graph = square();
    graph.points.push_back({1, 1});  // 4: a copy of point 2
    graph.points.push_back({5, 5});  // 5: isolated
    // Reversed duplicate, self-loop, duplicate through the copy, and between the copy and its original.
    graph.edges.insert(graph.edges.end(), {{1, 0}, {2, 2}, {4, 3}, {2, 4}});
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{0, 1, 2, 3}, {}, 1.0}}));
    EXPECT_EQ(result.ignoredEdges, 4u);
    EXPECT_EQ(result.ignoredPoints, 2u);
}

TEST(StreetBlocks, ACopiedPointsEdgesMoveToTheFirstPointAtItsPlace) {
    Graph graph{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 1}}, {{0, 1}, {1, 4}, {4, 3}, {3, 0}}};
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{0, 1, 2, 3}, {}, 1.0}}));
    EXPECT_EQ(result.ignoredEdges, 0u);
    EXPECT_EQ(result.ignoredPoints, 1u);
}

// Fig. 4.3.2's three cases that defeated the thesis' simple search, on one long cycle: a path
// along an earlier cycle, a dead end inside, and a cycle enclosed (hung on the boundary by a
// street, which is left out like a dead end; the cycle stays a hole).
TEST(StreetBlocks, TheSpecialCasesOfTheThesisFigure432) {
    Graph graph{{{0, 0},
                 {2, 0},
                 {4, 0},
                 {4, 2},
                 {4, 4},
                 {2, 4},
                 {0, 4},
                 {0, 2},  // 0–7: the long cycle
                 {1, 1},
                 {3, 1},
                 {3, 3},
                 {1, 3},    // 8–11: the enclosed cycle
                 {0.5, 2},  // 12: the dead end's end
                 {6, 0},
                 {6, 2}},  // 13–14: an earlier cycle beside it
                {}};
    graph.addRing({0, 1, 2, 3, 4, 5, 6, 7});
    graph.addRing({8, 9, 10, 11});
    graph.edges.insert(graph.edges.end(), {{1, 9}, {7, 12}, {2, 13}, {13, 14}, {14, 3}});
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks,
              (std::vector<StreetBlock>{
                  {{0, 1, 2, 3, 4, 5, 6, 7}, {{8, 11, 10, 9}}, 12}, {{2, 13, 14, 3}, {}, 4}, {{8, 9, 10, 11}, {}, 4}}));
}

TEST(StreetBlocksNonSimple, AFaceTouchingItselfIsCountedNotReturned) {
    // A triangle inside the square touching its corner: the face between them passes 0 twice.
    Graph graph{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}, {1, 2}}, {}};
    graph.addRing({0, 1, 2, 3});
    graph.addRing({0, 4, 5});
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{0, 4, 5}, {}, 1.5}}));
    EXPECT_EQ(result.nonSimpleFaces, 1u);
}

TEST(StreetBlocksNonSimple, APinchedHoleMakesItsFaceNotSimple) {
    // Two triangles meeting at a point, loose inside a square.
    Graph graph{{{0, 0}, {6, 0}, {6, 6}, {0, 6}, {1, 2}, {3, 3}, {1, 4}, {5, 2}, {5, 4}}, {}};
    graph.addRing({0, 1, 2, 3});
    graph.addRing({4, 5, 6});
    graph.addRing({5, 7, 8});
    BlockResult result = blocksOf(graph);
    EXPECT_EQ(result.blocks, (std::vector<StreetBlock>{{{4, 5, 6}, {}, 2}, {{5, 7, 8}, {}, 2}}));
    EXPECT_EQ(result.nonSimpleFaces, 1u);
}

TEST(StreetBlocksRobustness, ASliverIsFoundByExactPredicates) {
    // (1, 1/3) and (3, 1) seen from the origin differ by 5.6e-17 in the cross product, which
    // rounds to 0 in doubles (so the plain checks of expectSound cannot judge it).
    Graph graph{{{0, 0}, {1, 1.0 / 3}, {3, 1}}, {}};
    graph.addRing({0, 1, 2});
    BlockResult result = bothWays(graph);
    ASSERT_EQ(result.blocks.size(), 1u);
    EXPECT_EQ(result.blocks[0].boundary, (Ring{0, 1, 2}));
    EXPECT_GT(result.blocks[0].area, 0);
}

TEST(StreetBlocksRobustness, CoordinatesAtTheLimitsWork) {
    for (double scale : {1e99, 1e-99}) {
        Graph graph = square();
        for (PlanarPoint &p : graph.points) p = {p.x * scale + scale / 4, p.y * scale};
        BlockResult result = blocksOf(graph);
        ASSERT_EQ(result.blocks.size(), 1u) << scale;
        EXPECT_EQ(result.blocks[0].boundary, (Ring{0, 1, 2, 3}));
        EXPECT_NEAR(result.blocks[0].area, scale * scale, 1e-12 * scale * scale);
    }
}

TEST(StreetBlocksRobustness, CrossingEdgesMakeInvalidFacesInTheArrangement) {
    // Both diagonals of a square, without a point where they cross.
    Graph graph = square();
    graph.edges.insert(graph.edges.end(), {{0, 2}, {1, 3}});
    BlockResult result = blocksByArrangement(graph.points, graph.edges);
    EXPECT_TRUE(result.blocks.empty());
    EXPECT_EQ(result.invalidFaces, 4u);
    EXPECT_EQ(result.unmatchedEdges, 4u);  // the diagonals' halves
    EXPECT_NO_THROW(blocksByFaceWalk(graph.points, graph.edges));
}

TEST(StreetBlocksRobustness, AnEdgeEndingOnAnotherMakesInvalidFacesInTheArrangement) {
    Graph graph{{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 4}, {2, 0}}, {{0, 1}, {1, 2}, {2, 4}, {4, 3}, {3, 0}, {4, 5}}};
    BlockResult result = blocksByArrangement(graph.points, graph.edges);
    EXPECT_TRUE(result.blocks.empty());
    EXPECT_EQ(result.invalidFaces, 2u);
    EXPECT_EQ(result.unmatchedEdges, 2u);  // the bottom edge's halves
    EXPECT_NO_THROW(blocksByFaceWalk(graph.points, graph.edges));
}

TEST(StreetBlocksLimits, BadInputIsRefused) {
    auto refused = [](const Graph &graph) {
        EXPECT_THROW(blocksByArrangement(graph.points, graph.edges), std::invalid_argument);
        EXPECT_THROW(blocksByFaceWalk(graph.points, graph.edges), std::invalid_argument);
    };
    Graph graph = square();
    graph.edges.emplace_back(3, 4);
    refused(graph);
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1.1e100,
                       -1.1e100, 0.9e-100}) {
        graph = square();
        graph.points[2].y = bad;
        refused(graph);
    }
    graph = {};
    graph.edges.resize(kMaxBlockGraphSize + 1);
    refused(graph);
}

// ---- Random plane graphs ----

// A jittered n×n grid of points 10 apart, each cell cut into two triangles by its rising diagonal.
// Each grid edge and diagonal is kept with probability `along` when its ends lie on the same square
// ring around the grid's centre, else `across`: a low `across` leaves loops inside loops.
struct RandomGrid {
    Graph graph;
    std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise
};

RandomGrid randomGrid(uint32_t seed, uint32_t n, double along, double across) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-2.5, 2.5), unit(0, 1);
    RandomGrid grid;
    auto at = [n](uint32_t i, uint32_t j) { return j * n + i; };
    auto ring = [n](uint32_t i, uint32_t j) {
        int twiceCentre = int(n) - 1;
        return std::max(std::abs(2 * int(i) - twiceCentre), std::abs(2 * int(j) - twiceCentre));
    };
    for (uint32_t j = 0; j < n; ++j) {
        for (uint32_t i = 0; i < n; ++i)
            grid.graph.points.push_back({10.0 * i + jitter(random), 10.0 * j + jitter(random)});
    }
    auto maybe = [&](uint32_t i, uint32_t j, uint32_t k, uint32_t l) {
        if (unit(random) < (ring(i, j) == ring(k, l) ? along : across))
            grid.graph.edges.emplace_back(at(i, j), at(k, l));
    };
    for (uint32_t j = 0; j < n; ++j) {
        for (uint32_t i = 0; i < n; ++i) {
            if (i + 1 < n) maybe(i, j, i + 1, j);
            if (j + 1 < n) maybe(i, j, i, j + 1);
            if (i + 1 < n && j + 1 < n) {
                maybe(i, j, i + 1, j + 1);
                grid.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                grid.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    return grid;
}

// The bounded faces as the grid's triangles see them: triangles joined across every missing
// edge, and those on the grid's edge to the outside. Each group not joined to the outside is one
// bounded face; its area is theirs.
struct TriangleFaces {
    std::vector<size_t> faceOf;      // per triangle; `outside` for the unbounded face
    std::map<size_t, double> areas;  // per bounded face
    size_t outside = 0;
};

size_t rootOf(std::vector<size_t> &parent, size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

TriangleFaces triangleFaces(const RandomGrid &grid) {
    std::set<PlanarEdge> kept;
    for (const auto &[a, b] : grid.graph.edges) kept.emplace(std::min(a, b), std::max(a, b));
    std::map<PlanarEdge, std::vector<size_t>> sides;
    for (size_t t = 0; t < grid.triangles.size(); ++t) {
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = grid.triangles[t][k], b = grid.triangles[t][(k + 1) % 3];
            sides[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    }
    TriangleFaces faces;
    faces.outside = grid.triangles.size();
    std::vector<size_t> parent(grid.triangles.size() + 1);
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto &[edge, triangles] : sides) {
        if (kept.contains(edge)) continue;
        size_t other = triangles.size() == 2 ? triangles[1] : faces.outside;
        parent[rootOf(parent, triangles[0])] = rootOf(parent, other);
    }
    size_t outsideRoot = rootOf(parent, faces.outside);
    for (size_t t = 0; t < grid.triangles.size(); ++t) {
        size_t root = rootOf(parent, t);
        faces.faceOf.push_back(root == outsideRoot ? faces.outside : root);
        if (root == outsideRoot) continue;
        const auto &[a, b, c] = grid.triangles[t];
        faces.areas[root] += twiceArea(grid.graph.points, {a, b, c}) / 2;
    }
    return faces;
}

size_t triangleAt(const RandomGrid &grid, const PlanarPoint &p) {
    for (size_t t = 0; t < grid.triangles.size(); ++t) {
        if (inRing(grid.graph.points, {grid.triangles[t].begin(), grid.triangles[t].end()}, p)) return t;
    }
    return grid.triangles.size();
}

size_t strayPoints(const Graph &graph) {
    std::set<uint32_t> used;
    for (const auto &[a, b] : graph.edges) used.insert({a, b});
    return graph.points.size() - used.size();
}

TEST(StreetBlocksProperty, RandomPlaneGraphsGiveTheSameSoundBlocksBothWays) {
    size_t holes = 0, nonSimple = 0, blocks = 0;
    for (uint32_t seed = 0; seed < 200; ++seed) {
        // Odd seeds keep all edges alike, even ones mostly the rings'.
        uint32_t n = 2 + (seed / 2) % 12;
        bool rings = seed % 2 == 0;
        double along = rings ? 0.9 : 0.4 + 0.05 * (seed % 9);
        double across = rings ? 0.05 + 0.05 * (seed % 3) : along;
        RandomGrid grid = randomGrid(seed, n, along, across);
        SCOPED_TRACE(testing::Message() << "seed " << seed << ", " << n << "×" << n << ", keep " << along << ", "
                                        << across);
        BlockResult result = blocksOf(grid.graph);
        EXPECT_EQ(result.ignoredEdges, 0u);
        EXPECT_EQ(result.ignoredPoints, strayPoints(grid.graph));
        // Each block is one of the triangles' bounded faces, with its area; the faces left over
        // are those counted as not simple.
        TriangleFaces faces = triangleFaces(grid);
        std::set<size_t> matched;
        for (const StreetBlock &block : result.blocks) {
            size_t t = triangleAt(grid, pointInside(grid.graph.points, block));
            ASSERT_LT(t, grid.triangles.size());
            size_t face = faces.faceOf[t];
            ASSERT_NE(face, faces.outside);
            EXPECT_TRUE(matched.insert(face).second);
            EXPECT_NEAR(block.area, faces.areas[face], 1e-9 * faces.areas[face]);
            holes += block.holes.size();
        }
        EXPECT_EQ(result.blocks.size() + result.nonSimpleFaces, faces.areas.size());
        nonSimple += result.nonSimpleFaces;
        blocks += result.blocks.size();
    }
    // The seeds reach every kind of face.
    EXPECT_GT(blocks, 1000u);
    EXPECT_GT(holes, 0u);
    EXPECT_GT(nonSimple, 0u);
}

}  // namespace
}  // namespace veduta
