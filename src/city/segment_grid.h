// Line segments sorted into square cells, each under every cell its box reaches when widened
// by a reach of its own: the segments that may lie within reach of a point are those of the
// point's cell. The street-edge search of the OSM import asks it for every lot corner, which
// would otherwise measure every corner against every street of a town.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

class SegmentGrid {
  public:
    struct Segment {
        Vec2f a, b;
        float reach;
        uint32_t owner;  // what the caller knows the segment by (a street)
    };

    explicit SegmentGrid(float cellSize) : cellSize_(cellSize) {}

    void add(const Segment &segment);

    // Calls `visit` with every segment whose widened box may hold `p`: a superset of those
    // within their reach of it.
    template <typename Visit>
    void forEachNear(Vec2f p, Visit visit) const {
        for (uint32_t index : long_) visit(segments_[index]);
        auto cell = cells_.find(key(cellOf(p.x), cellOf(p.y)));
        if (cell == cells_.end()) return;
        for (uint32_t index : cell->second) visit(segments_[index]);
    }

    // Calls `visit` with every segment whose widened box may meet the box from `low` to `high`,
    // some more than once.
    template <typename Visit>
    void forEachNear(Vec2f low, Vec2f high, Visit visit) const {
        for (uint32_t index : long_) visit(segments_[index]);
        int64_t x0 = cellOf(low.x), x1 = cellOf(high.x), y0 = cellOf(low.y), y1 = cellOf(high.y);
        if ((x1 - x0 + 1) > kMaxCells / (y1 - y0 + 1)) {  // a box over many cells: all of them
            for (const Segment &segment : segments_) visit(segment);
            return;
        }
        for (int64_t x = x0; x <= x1; ++x) {
            for (int64_t y = y0; y <= y1; ++y) {
                auto cell = cells_.find(key(x, y));
                if (cell == cells_.end()) continue;
                for (uint32_t index : cell->second) visit(segments_[index]);
            }
        }
    }

  private:
    // A segment whose box covers more cells than this is asked by every point instead.
    static constexpr int64_t kMaxCells = 4096;

    int64_t cellOf(float coordinate) const;
    // Distinct cells may share a key; they then share their segments, which only adds candidates.
    static uint64_t key(int64_t x, int64_t y) { return uint64_t(x) * 0x9E3779B97F4A7C15ull ^ uint64_t(y); }

    float cellSize_;
    std::vector<Segment> segments_;
    std::vector<uint32_t> long_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

}  // namespace veduta
