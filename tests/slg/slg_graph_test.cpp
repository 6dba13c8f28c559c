// The SLG's structure and its manipulations (digest-003 §2.1, §2.4).
#include <gtest/gtest.h>

#include "slg/slg_graph.h"

namespace veduta {
namespace {

std::vector<EdgeLocation> streets(size_t n) { return std::vector<EdgeLocation>(n, EdgeLocation::Street); }

TEST(SlgGraph, AnOutlineIsItsCornersJoinedInOrder) {
    Polygon2d square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    SlgGraph graph = outlineGraph(square, streets(4));
    ASSERT_EQ(graph.nodes().size(), 4u);
    ASSERT_EQ(graph.edges().size(), 4u);
    for (SlgEdgeId e = 0; e < 4; ++e) {
        EXPECT_EQ(graph.edge(e).start, e);
        EXPECT_EQ(graph.edge(e).end, (e + 1) % 4);
        EXPECT_TRUE(graph.edge(e).outer);
    }
}

TEST(SlgGraph, OnlyTheConcaveCornerOfAnLIsReflex) {
    Polygon2d l = {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
    SlgGraph graph = outlineGraph(l, streets(6));
    for (SlgNodeId n = 0; n < 6; ++n) EXPECT_EQ(graph.node(n).reflex, n == 3) << n;
}

TEST(SlgGraph, SplittingAnEdgeKeepsItsLocationOnBothPieces) {
    // L1692: a centred 1 m window on a 4 m edge is a split at 1.5 m, then of the 2.5 m rest at 1 m.
    SlgGraph graph;
    SlgNodeId a = graph.addNode({0, 0}, SlgNodeType::Corner), b = graph.addNode({4, 0}, SlgNodeType::Corner);
    SlgEdgeId e = graph.addEdge(a, b, EdgeLocation::WindowToGap, true);
    SlgNodeId first = graph.splitEdge(e, 1.5 / 4, SlgNodeType::Inner);
    SlgEdgeId rest = graph.edgeBetween(first, b);
    SlgNodeId second = graph.splitEdge(rest, 1.0 / 2.5, SlgNodeType::Inner);
    EXPECT_DOUBLE_EQ(graph.position(first).x, 1.5);
    EXPECT_DOUBLE_EQ(graph.position(second).x, 2.5);
    EXPECT_EQ(graph.edge(e).end, first);
    for (const SlgEdge &edge : graph.edges()) EXPECT_EQ(edge.location, EdgeLocation::WindowToGap);
    EXPECT_EQ(graph.node(first).edges.size(), 2u);
    EXPECT_EQ(graph.node(b).edges.size(), 1u);
}

TEST(SlgGraph, CollinearEdgesMergeOnlyWhenNothingElseMeetsThem) {
    SlgGraph graph;
    SlgNodeId a = graph.addNode({0, 0}, SlgNodeType::Corner), b = graph.addNode({2, 0}, SlgNodeType::Inner),
              c = graph.addNode({5, 0}, SlgNodeType::Corner), d = graph.addNode({5, 3}, SlgNodeType::Corner);
    SlgEdgeId ab = graph.addEdge(a, b, EdgeLocation::Gap, true), bc = graph.addEdge(b, c, EdgeLocation::Gap, true);
    SlgEdgeId cd = graph.addEdge(c, d, EdgeLocation::Gap, true);
    EXPECT_FALSE(graph.mergeCollinear(bc, cd));  // a corner: not eq 14's 0°
    SlgNodeId spur = graph.addNode({2, 1}, SlgNodeType::Inner);
    SlgEdgeId toSpur = graph.addEdge(b, spur, EdgeLocation::Gap, false);
    EXPECT_FALSE(graph.mergeCollinear(ab, bc));  // b holds a third edge
    graph.removeEdge(toSpur);
    ASSERT_TRUE(graph.mergeCollinear(ab, bc));
    EXPECT_EQ(graph.edge(ab).end, c);
    EXPECT_TRUE(graph.edge(bc).removed);
    EXPECT_EQ(graph.edgeBetween(a, c), ab);
    EXPECT_EQ(graph.node(b).edges.size(), 0u);
}

TEST(SlgGraph, AClockwiseLoopIsTurnedCounterClockwiseWithItsEdges) {
    SlgGraph graph;
    std::vector<SlgNodeId> n;
    for (Vec2d p : {Vec2d{0, 0}, Vec2d{0, 4}, Vec2d{3, 4}, Vec2d{3, 0}})
        n.push_back(graph.addNode(p, SlgNodeType::Corner));
    SlgPath path{n, {}};
    for (size_t i = 0; i < 4; ++i) path.edges.push_back(graph.addEdge(n[i], n[(i + 1) % 4], EdgeLocation::Gap, true));
    ASSERT_LT(signedArea(graph.polygon(path)), 0);
    orderCounterClockwise(graph, path);
    EXPECT_DOUBLE_EQ(signedArea(graph.polygon(path)), 12);
    for (size_t i = 0; i < 4; ++i) {
        const SlgEdge &e = graph.edge(path.edges[i]);
        EXPECT_TRUE(e.touches(path.nodes[i]) && e.touches(path.nodes[(i + 1) % 4])) << i;
    }
}

TEST(SlgGraph, PathTypesFollowTheirOuterEdgesAndCorners) {
    Polygon2d l = {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
    SlgGraph graph = outlineGraph(l, streets(6));
    SlgNodeId inner = graph.addNode({5, 5}, SlgNodeType::Inner);
    SlgPath front{
        {0, 1, inner},
        {0, graph.addEdge(1, inner, EdgeLocation::Gap, false), graph.addEdge(inner, 0, EdgeLocation::Gap, false)}};
    EXPECT_EQ(graph.pathType(front), SlgPathType::Border);  // one outer edge
    SlgPath corner{{0, 1, 2, inner},
                   {0, 1, graph.addEdge(2, inner, EdgeLocation::Gap, false), graph.edgeBetween(inner, 0)}};
    EXPECT_EQ(graph.pathType(corner), SlgPathType::BorderWithCorner);
    SlgPath concave{
        {2, 3, 4, inner},
        {2, 3, graph.addEdge(4, inner, EdgeLocation::Gap, false), graph.addEdge(inner, 2, EdgeLocation::Gap, false)}};
    EXPECT_EQ(graph.pathType(concave), SlgPathType::BorderWithConcaveCorner);
    SlgNodeId other = graph.addNode({6, 6}, SlgNodeType::Inner), third = graph.addNode({5, 7}, SlgNodeType::Inner);
    SlgPath innerPath{
        {inner, other, third},
        {graph.addEdge(inner, other, EdgeLocation::Gap, false), graph.addEdge(other, third, EdgeLocation::Gap, false),
         graph.addEdge(third, inner, EdgeLocation::Gap, false)}};
    EXPECT_EQ(graph.pathType(innerPath), SlgPathType::Inner);
}

TEST(EdgeLocation, FourteenNamesEachReadBack) {
    for (int i = 0; i < kEdgeLocationCount; ++i) {
        auto location = EdgeLocation(i);
        EXPECT_EQ(locationNamed(locationName(location)), location) << i;
    }
    EXPECT_FALSE(locationNamed("balcony"));
    EXPECT_TRUE(isWindow(EdgeLocation::WindowToStreet));
    EXPECT_TRUE(isDoor(EdgeLocation::InnerStairEntrance));
    EXPECT_TRUE(isOuter(EdgeLocation::Entrance));
    EXPECT_FALSE(isOuter(EdgeLocation::HouseCorridor));
}

}  // namespace
}  // namespace veduta
