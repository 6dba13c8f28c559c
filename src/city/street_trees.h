// Street trees: an avenue's broadleaf trees along both kerbs of every street wide enough for
// them, standing in the sidewalk, spaced evenly, kept out of junctions and off every other
// street. Placed by the city's seed and each street's index; docs/citydata.md.
#pragma once

#include <cstdint>
#include <vector>

#include "city/street_geometry.h"
#include "geo/tree_placement.h"

namespace veduta {

struct StreetTreeOptions {
    float minimumWidth = 8;  // carriageway metres from which a street gets trees
    float spacing = 10;      // metres between trees along a kerb
    float fromKerb = 1.0f;   // metres into the sidewalk
    float height = 9;        // metres, give or take a tenth
};

// The trees, in the network's plan (z is the caller's: the street's height or the terrain's).
std::vector<PlacedTree> streetTrees(const StreetNetwork &network, const StreetStyle &style, uint32_t seed,
                                    const StreetTreeOptions &options = {});

}  // namespace veduta
