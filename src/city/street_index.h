// A street network's streets by grid cell (segment_grid.h), so that the streets near a block are
// found without measuring every street of the town: buildableAreas asks once per block, and
// across a city of n blocks that made cutting the lots grow as n² (issue 21).
#pragma once

#include <cstdint>
#include <vector>

#include "city/segment_grid.h"
#include "city/street_geometry.h"
#include "core/vecmath.h"

namespace veduta {

class StreetIndex {
  public:
    explicit StreetIndex(const StreetNetwork &network);

    // The streets whose carriageway, `extra` wider on either side, may reach into the box from
    // `low` to `high`: their indices, ascending; a few that do not reach it may be among them.
    std::vector<uint32_t> near(Vec2f low, Vec2f high, float extra) const;

  private:
    // About half a block of a Gründerzeit grid: a block's box meets a few cells.
    static constexpr float kCell = 64;
    SegmentGrid grid_{kCell};
};

}  // namespace veduta
