// The street graph in GraphViz's DOT, to look at what the growth built: every vertex at its
// place in metres (`neato -n2 -Tsvg` draws it to scale), static vertices (splits) red, and
// every street as an undirected edge; vertices and streets off the ground level are blue.
#pragma once

#include <string>

#include "streets/street_graph.h"

namespace veduta {

// Positions in points of 1 m, x east, y north, one decimal; each vertex's id and height as
// its tooltip. `heightTolerance` is the constraints' (street_constraints.h): within it of
// height 0 a vertex is on the ground.
std::string toDot(const StreetGraph &graph, float heightTolerance);

}  // namespace veduta
