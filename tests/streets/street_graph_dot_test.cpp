#include "streets/street_graph_dot.h"

#include <gtest/gtest.h>

namespace veduta {
namespace {

TEST(StreetGraphDot, PlacesVerticesInMetresAndColoursSplitsAndOtherLevels) {
    StreetGraph graph;
    VertexId a = graph.addVertex({0, 0, 0}), b = graph.addVertex({80, -0.04f, 0}), up = graph.addVertex({80, 40, 12});
    graph.addEdge(a, b);
    graph.addEdge(b, up);
    graph.splitEdge(0, {40, 0, 0});
    EXPECT_EQ(toDot(graph, 0.5f),
              "graph streets {\n"
              "node [shape=point, width=0.05];\n"
              "0 [pos=\"0.0,0.0\", color=black, tooltip=\"0 at height 0.0\"];\n"
              "1 [pos=\"80.0,0.0\", color=black, tooltip=\"1 at height 0.0\"];\n"
              "2 [pos=\"80.0,40.0\", color=blue, tooltip=\"2 at height 12.0\"];\n"
              "3 [pos=\"40.0,0.0\", color=red, tooltip=\"3 at height 0.0\"];\n"
              "0 -- 3 [color=black];\n"
              "1 -- 2 [color=blue];\n"
              "3 -- 1 [color=black];\n"
              "}\n");
}

}  // namespace
}  // namespace veduta
