// Blocks for the lot tests: named shapes, and random convex and star-shaped ones.
#pragma once

#include <cstdint>
#include <vector>

#include "city/lot_subdivision.h"

namespace veduta {

struct NamedBlock {
    const char *name;
    Block block;
};

// Rectangles (streets all round, on one side, on two), an L, a U (concave), a pentagon, a
// hexagon, a heptagon and an octagon with 6 m corners cut off, all counter-clockwise.
const std::vector<NamedBlock> &shapeBlocks();

// Block `index` of a family of random blocks, up to 150 m across: the convex hull of 3 to 10
// random points (even indices) or a star of 4 to 10 points at increasing angles round a centre,
// at random distances (odd ones); each edge a street with probability 3/4. A pure function of
// `index`.
Block randomBlock(uint32_t index);

}  // namespace veduta
