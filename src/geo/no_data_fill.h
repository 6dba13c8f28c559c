// Holes in a DGM filled from the nodes around them.
#pragma once

#include <cstddef>

#include "geo/height_grid.h"

namespace veduta {

// Gives every NaN node a height, ring by ring from the edge of the hole inwards: each node
// of a ring gets the mean of its (up to 8) neighbours that had a height before that ring.
// Deterministic and linear in the number of filled nodes. Returns how many were filled;
// a grid with no height at all is left as it is (returns 0).
size_t fillNoData(HeightGrid &grid);

// The number of NaN nodes.
size_t countNoData(const HeightGrid &grid);

}  // namespace veduta
