// The word graph in GraphViz's DOT, in the form of Goitowski 2010, Listing 4.5: a debugging
// view of every node (its symbol, position and id; draw nodes yellow) and of both directions
// of every link (successors blue, predecessors red).
#pragma once

#include <string>

#include "streets/word_graph.h"

namespace veduta {

// Positions in veduta's frame (z up), one decimal, as the thesis prints them.
std::string toDot(const WordGraph &graph);

}  // namespace veduta
