// Party walls (Brandwände): the footprint edges along which two buildings of a row stand wall to
// wall. Such an edge gets no facade of the rules but a plain wall in the material `party_wall`,
// which shows where the neighbour is lower or shorter, as the blind side walls of a Gründerzeit
// row do. docs/buildings.md.
#pragma once

#include <span>
#include <vector>

#include "city/footprint.h"

namespace veduta {

// Per footprint, one flag an edge: whether it runs back to back along another footprint's
// edge (opposite directions within 2°, the other edge within 0.1 m of its line, covering at
// least half its length).
std::vector<std::vector<bool>> partyWalls(std::span<const Footprint *const> footprints);

}  // namespace veduta
