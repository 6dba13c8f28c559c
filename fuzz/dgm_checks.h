// What every DGM reader promises of the grid it returns (geo/height_grid.h), checked on each
// fuzz input that reads: a crash here is a reader that let bad input through.
#pragma once

#include <cmath>
#include <cstdlib>

#include "geo/height_grid.h"

namespace veduta::fuzz {

inline void checkGrid(const HeightGrid &grid) {
    bool shaped = grid.columns > 0 && grid.rows > 0 && grid.spacing > 0 && std::isfinite(grid.spacing) &&
        std::isfinite(grid.west) && std::isfinite(grid.south) &&
        grid.heights.size() == size_t(grid.columns) * size_t(grid.rows);
    if (!shaped) std::abort();
    for (float h : grid.heights) {
        if (!std::isnan(h) && !(std::abs(h) <= kMaxHeight)) std::abort();
    }
}

}  // namespace veduta::fuzz
