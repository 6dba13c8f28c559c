// Holes in a DGM filled from the nodes around them, as far as filling is interpolation rather
// than invention.
#pragma once

#include <cstddef>

#include "geo/height_grid.h"

namespace veduta {

struct NoDataFill {
    size_t filled = 0;    // nodes given a height
    size_t cut = 0;       // nodes of holes that reach farther, left NaN
    size_t cutHoles = 0;  // how many such holes (8-connected)
};

// Fills the holes of the grid (its NaN nodes, 8-connected) whose every node lies within
// `maxDistance` rings of a node with a height, ring by ring from the edge of the hole inwards:
// each node of a ring gets the mean of its (up to 8) neighbours that had a height before that
// ring. A hole that reaches farther is left NaN as a whole: filled, it would be made-up
// terrain. Deterministic and linear in the grid's nodes; a grid with no height at all is left
// as it is.
NoDataFill fillNoData(HeightGrid &grid, int maxDistance);

// The number of NaN nodes.
size_t countNoData(const HeightGrid &grid);

}  // namespace veduta
