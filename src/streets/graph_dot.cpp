#include "streets/graph_dot.h"

#include <fmt/format.h>
#include <cmath>

namespace veduta {

namespace {

// One decimal; a value that rounds to zero prints as 0.0, never -0.0.
float printable(float value) { return std::round(value * 10) == 0 ? 0.0f : value; }

std::string label(const WordNode &node) {
    // `\` (the roll) is DOT's escape character inside a quoted label.
    std::string symbol = node.word.symbol == '\\' ? "\\\\" : std::string(1, node.word.symbol);
    const Vec3f &p = node.turtle.position;
    return fmt::format("{}({:.1f}, {:.1f}, {:.1f})\\nid:{}", symbol, printable(p.x), printable(p.y), printable(p.z),
                       node.id);
}

}  // namespace

std::string toDot(const WordGraph &graph) {
    std::string dot = "digraph G {\n";
    for (const WordNode &node : graph.nodes()) {
        const char *fill = graph.isDrawNode(node.id) ? ", style=filled, fillcolor=yellow" : "";
        dot += fmt::format("{} [label=\"{}\"{}];\n", node.id, label(node), fill);
    }
    for (const WordNode &node : graph.nodes()) {
        // Last-linked successor first, as Listing 4.5 lists node 1's: 14, 10, 6, 2.
        for (auto next = node.successors.rbegin(); next != node.successors.rend(); ++next)
            dot += fmt::format("{}->{}[label=\"\", color=blue];\n", node.id, *next);
        for (NodeId before : node.predecessors) dot += fmt::format("{}->{}[label=\"\", color=red];\n", node.id, before);
    }
    return dot + "}\n";
}

}  // namespace veduta
