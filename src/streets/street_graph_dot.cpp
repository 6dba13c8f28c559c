#include "streets/street_graph_dot.h"

#include <fmt/format.h>
#include <cmath>

namespace veduta {

namespace {

// One decimal; a value that rounds to zero prints as 0.0, never -0.0.
float printable(float value) { return std::round(value * 10) == 0 ? 0.0f : value; }

}  // namespace

std::string toDot(const StreetGraph &graph, float heightTolerance) {
    auto onTheGround = [&](VertexId v) { return std::abs(graph.vertex(v).position.z) <= heightTolerance; };
    std::string dot = "graph streets {\nnode [shape=point, width=0.05];\n";
    for (VertexId v = 0; v < graph.vertices().size(); ++v) {
        const StreetVertex &vertex = graph.vertex(v);
        const Vec3f &p = vertex.position;
        const char *colour = vertex.isStatic ? "red" : onTheGround(v) ? "black" : "blue";
        dot += fmt::format("{} [pos=\"{:.1f},{:.1f}\", color={}, tooltip=\"{} at height {:.1f}\"];\n", v,
                           printable(p.x), printable(p.y), colour, v, printable(p.z));
    }
    for (const StreetEdge &e : graph.edges()) {
        const char *colour = onTheGround(e.a) && onTheGround(e.b) ? "black" : "blue";
        dot += fmt::format("{} -- {} [color={}];\n", e.a, e.b, colour);
    }
    return dot + "}\n";
}

}  // namespace veduta
