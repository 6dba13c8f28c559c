#include "city/segment_grid.h"

#include <algorithm>
#include <cmath>

namespace veduta {

int64_t SegmentGrid::cellOf(float coordinate) const {
    // Far coordinates share the outermost cells rather than overflow the cell index.
    return int64_t(std::clamp(std::floor(double(coordinate) / cellSize_), -1e12, 1e12));
}

void SegmentGrid::add(const Segment &segment) {
    auto index = uint32_t(segments_.size());
    segments_.push_back(segment);
    int64_t x0 = cellOf(std::min(segment.a.x, segment.b.x) - segment.reach);
    int64_t x1 = cellOf(std::max(segment.a.x, segment.b.x) + segment.reach);
    int64_t y0 = cellOf(std::min(segment.a.y, segment.b.y) - segment.reach);
    int64_t y1 = cellOf(std::max(segment.a.y, segment.b.y) + segment.reach);
    if ((x1 - x0 + 1) > kMaxCells / (y1 - y0 + 1)) {
        long_.push_back(index);
        return;
    }
    for (int64_t x = x0; x <= x1; ++x)
        for (int64_t y = y0; y <= y1; ++y) cells_[key(x, y)].push_back(index);
}

}  // namespace veduta
