#include "geo/no_data_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

// What each node is while the holes are filled.
enum State : uint8_t {
    kEmpty,   // no height, not reached yet
    kNext,    // no height, in the next ring
    kData,    // a height of the file
    kFilled,  // a height from a ring
    kCut,     // in a hole that reaches too far: NaN again
};

// Gives `ring`'s nodes the mean of their neighbours with a height and returns the next ring.
std::vector<size_t> fillRing(HeightGrid &grid, std::vector<uint8_t> &state, const std::vector<size_t> &ring) {
    std::vector<float> values;
    values.reserve(ring.size());
    for (size_t i : ring) {
        double sum = 0;
        int count = 0;
        forEachNeighbour(grid, i, [&](size_t n) {
            if (state[n] == kData || state[n] == kFilled) sum += grid.heights[n], ++count;
        });
        values.push_back(float(sum / count));
    }
    for (size_t k = 0; k < ring.size(); ++k) grid.heights[ring[k]] = values[k], state[ring[k]] = kFilled;
    std::vector<size_t> next;
    for (size_t i : ring) {
        forEachNeighbour(grid, i, [&](size_t n) {
            if (state[n] == kEmpty) state[n] = kNext, next.push_back(n);
        });
    }
    return next;
}

struct CutHole {
    size_t nodes = 0;
    size_t wereFilled = 0;  // of them, by the rings before
};

// Makes the whole hole around `start` NaN again: every node without a file height that is
// 8-connected to it.
CutHole cutHole(HeightGrid &grid, std::vector<uint8_t> &state, size_t start) {
    CutHole hole;
    std::vector<size_t> stack;
    auto take = [&](size_t n) {
        hole.wereFilled += state[n] == kFilled;
        state[n] = kCut;
        stack.push_back(n);
    };
    take(start);
    while (!stack.empty()) {
        size_t i = stack.back();
        stack.pop_back();
        grid.heights[i] = std::numeric_limits<float>::quiet_NaN();
        ++hole.nodes;
        forEachNeighbour(grid, i, [&](size_t n) {
            if (state[n] != kData && state[n] != kCut) take(n);
        });
    }
    return hole;
}

}  // namespace

size_t countNoData(const HeightGrid &grid) {
    return size_t(std::count_if(grid.heights.begin(), grid.heights.end(), [](float h) { return std::isnan(h); }));
}

NoDataFill fillNoData(HeightGrid &grid, int maxDistance) {
    NoDataFill result;
    if (countNoData(grid) == grid.heights.size()) return result;
    std::vector<uint8_t> state(grid.heights.size());
    for (size_t i = 0; i < grid.heights.size(); ++i) state[i] = std::isnan(grid.heights[i]) ? kEmpty : kData;
    std::vector<size_t> ring;
    for (size_t i = 0; i < grid.heights.size(); ++i) {
        if (state[i] != kData) continue;
        forEachNeighbour(grid, i, [&](size_t n) {
            if (state[n] == kEmpty) state[n] = kNext, ring.push_back(n);
        });
    }
    for (int distance = 1; distance <= maxDistance && !ring.empty(); ++distance) {
        result.filled += ring.size();
        ring = fillRing(grid, state, ring);
    }
    // What is left without a height lies in holes that reach farther: cut each whole.
    for (size_t i = 0; i < grid.heights.size(); ++i) {
        if (state[i] != kEmpty && state[i] != kNext) continue;
        CutHole hole = cutHole(grid, state, i);
        result.cut += hole.nodes;
        result.filled -= hole.wereFilled;
        ++result.cutHoles;
    }
    return result;
}

}  // namespace veduta
