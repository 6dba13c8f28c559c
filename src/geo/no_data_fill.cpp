#include "geo/no_data_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace veduta {

namespace {

// Calls visit(index) for the up to 8 neighbours of node `index`.
template <class Visit>
void forEachNeighbour(const HeightGrid &grid, size_t index, Visit &&visit) {
    int column = int(index % size_t(grid.columns)), row = int(index / size_t(grid.columns));
    for (int r = std::max(row - 1, 0); r <= std::min(row + 1, grid.rows - 1); ++r)
        for (int c = std::max(column - 1, 0); c <= std::min(column + 1, grid.columns - 1); ++c)
            if (c != column || r != row) visit(size_t(r) * size_t(grid.columns) + size_t(c));
}

}  // namespace

size_t countNoData(const HeightGrid &grid) {
    return size_t(std::count_if(grid.heights.begin(), grid.heights.end(), [](float h) { return std::isnan(h); }));
}

size_t fillNoData(HeightGrid &grid) {
    if (countNoData(grid) == grid.heights.size()) return 0;
    // 0: no height yet, 1: in the next ring, 2: has a height.
    std::vector<uint8_t> state(grid.heights.size());
    std::vector<size_t> ring;
    for (size_t i = 0; i < grid.heights.size(); ++i) state[i] = std::isnan(grid.heights[i]) ? 0 : 2;
    for (size_t i = 0; i < grid.heights.size(); ++i) {
        if (state[i] != 2) continue;
        forEachNeighbour(grid, i, [&](size_t n) {
            if (state[n] == 0) state[n] = 1, ring.push_back(n);
        });
    }
    size_t filled = 0;
    std::vector<float> values;
    std::vector<size_t> next;
    while (!ring.empty()) {
        values.clear();
        for (size_t i : ring) {
            double sum = 0;
            int count = 0;
            forEachNeighbour(grid, i, [&](size_t n) {
                if (state[n] == 2) sum += grid.heights[n], ++count;
            });
            values.push_back(float(sum / count));
        }
        for (size_t k = 0; k < ring.size(); ++k) grid.heights[ring[k]] = values[k], state[ring[k]] = 2;
        filled += ring.size();
        next.clear();
        for (size_t i : ring) {
            forEachNeighbour(grid, i, [&](size_t n) {
                if (state[n] == 0) state[n] = 1, next.push_back(n);
            });
        }
        ring.swap(next);
    }
    return filled;
}

}  // namespace veduta
