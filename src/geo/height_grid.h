// HeightGrid: a DGM, heights on a regular grid of a projected CRS, as every reader returns it
// (dgm_file.h) and as terrain meshing, draping and building placement read it.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "geodesy/map_point.h"

namespace veduta {

// The most nodes a DGM may have, read from one file or put together from tiles: 4 GB of
// heights, checked before they are allocated.
inline constexpr double kMaxGridNodes = 1e9;
// No height on Earth lies farther from sea level (metres): a height beyond is a broken file,
// or one in other units.
inline constexpr double kMaxHeight = 1e5;

struct HeightGrid {
    // Node (0, 0) is the south-west node; column c lies at west + c·spacing, row r at
    // south + r·spacing. Nodes are sample points (pixel centres of a raster), not cells.
    double west = 0, south = 0;
    double spacing = 0;  // metres, the same east–west and north–south
    int columns = 0, rows = 0;
    std::vector<float> heights;  // row-major from the south row; NaN where there is no data

    float node(int column, int row) const { return heights[size_t(row) * size_t(columns) + size_t(column)]; }
    float &node(int column, int row) { return heights[size_t(row) * size_t(columns) + size_t(column)]; }
    double east() const { return west + (columns - 1) * spacing; }
    double north() const { return south + (rows - 1) * spacing; }
    MapPoint nodePoint(int column, int row) const { return {west + column * spacing, south + row * spacing}; }
    bool empty() const { return columns == 0 || rows == 0; }
};

}  // namespace veduta
