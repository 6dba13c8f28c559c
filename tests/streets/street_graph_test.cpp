#include "streets/street_graph.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace veduta {
namespace {

TEST(StreetGraph, EdgesJoinDistinctVerticesOnce) {
    StreetGraph graph;
    VertexId a = graph.addVertex({0, 0, 0}), b = graph.addVertex({10, 0, 0});
    EdgeId e = graph.addEdge(a, b);
    EXPECT_EQ(graph.addEdge(b, a), e);
    EXPECT_EQ(graph.edges().size(), 1u);
    EXPECT_EQ(graph.edgeBetween(b, a), e);
    EXPECT_THROW(graph.addEdge(a, a), std::invalid_argument);
    EXPECT_THROW(graph.addEdge(a, 7), std::invalid_argument);
}

TEST(StreetGraph, SplittingAnEdgeKeepsItsEndsAndAddsAStaticVertex) {
    StreetGraph graph;
    VertexId a = graph.addVertex({0, 0, 0}), b = graph.addVertex({10, 0, 0});
    EdgeId e = graph.addEdge(a, b);
    VertexId middle = graph.splitEdge(e, {4, 0, 0});
    EXPECT_TRUE(graph.vertex(middle).isStatic);
    EXPECT_FALSE(graph.vertex(a).isStatic);
    EXPECT_EQ(graph.edgeBetween(a, middle), e);
    EdgeId rest = graph.edgeBetween(middle, b);
    ASSERT_NE(rest, UINT32_MAX);
    EXPECT_EQ(graph.edgeBetween(a, b), UINT32_MAX);
    EXPECT_EQ(graph.vertex(middle).edges, (std::vector<EdgeId>{e, rest}));
    EXPECT_EQ(graph.vertex(b).edges, (std::vector<EdgeId>{rest}));
}

TEST(StreetGraph, LookUpsFindWhatLiesNearASegmentAcrossCells) {
    StreetGraph graph(4);
    VertexId a = graph.addVertex({-30, -30, 0}), b = graph.addVertex({30, 30, 0});
    VertexId far = graph.addVertex({30, -30, 0});
    EdgeId diagonal = graph.addEdge(a, b);
    EXPECT_EQ(graph.edgesNear({0, 1, 0}, {0, 2, 0}, 0.5f), (std::vector<EdgeId>{diagonal}));
    EXPECT_TRUE(graph.edgesNear({10, -10, 0}, {12, -12, 0}, 0.5f).empty());
    EXPECT_EQ(graph.verticesNear({20, -30, 0}, {28, -30, 0}, 3), (std::vector<VertexId>{far}));
    EXPECT_EQ(graph.verticesNear({-40, -40, 0}, {40, 40, 0}, 0), (std::vector<VertexId>{a, b}));
}

TEST(StreetGraph, AnEdgeMovedBySplittingIsFoundWhereItIsNow) {
    StreetGraph graph(4);
    VertexId a = graph.addVertex({0, 0, 0}), b = graph.addVertex({40, 0, 0});
    EdgeId e = graph.addEdge(a, b);
    VertexId middle = graph.splitEdge(e, {10, 0, 0});
    EdgeId rest = graph.edgeBetween(middle, b);
    EXPECT_EQ(graph.edgesNear({30, -1, 0}, {30, 1, 0}, 0), (std::vector<EdgeId>{rest}));
    EXPECT_EQ(graph.edgesNear({5, -1, 0}, {5, 1, 0}, 0), (std::vector<EdgeId>{e}));
}

}  // namespace
}  // namespace veduta
