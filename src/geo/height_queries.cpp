#include "geo/height_queries.h"

#include <cmath>

namespace veduta {

namespace {

// Positions this close to a node (in spacings) are taken to be on it, so that a node's own
// map point, computed as west + c · spacing, gives the node's height exactly.
constexpr double kSnap = 1e-9;

struct CellPoint {
    int column = 0, row = 0;  // the cell's south-west node
    double fx = 0, fy = 0;    // position in the cell, 0…1
    float h00 = 0, h10 = 0, h01 = 0, h11 = 0;
};

// The cell that holds `p` (the last cell for points on the east or north edge), or nullopt
// outside the grid or when a corner of the cell is NaN.
bool locate(double position, int nodes, int &cell, double &fraction) {
    double rounded = std::round(position);
    if (std::abs(position - rounded) < kSnap) position = rounded;
    if (!(position >= 0 && position <= nodes - 1)) return false;
    cell = std::min(int(position), std::max(nodes - 2, 0));
    fraction = position - cell;
    return true;
}

std::optional<CellPoint> cellAt(const HeightGrid &grid, const MapPoint &p) {
    if (grid.empty()) return std::nullopt;
    CellPoint at;
    if (!locate((p.easting - grid.west) / grid.spacing, grid.columns, at.column, at.fx) ||
        !locate((p.northing - grid.south) / grid.spacing, grid.rows, at.row, at.fy))
        return std::nullopt;
    // A grid one node wide has no cells; its points are nodes (fraction 0).
    int c1 = std::min(at.column + 1, grid.columns - 1), r1 = std::min(at.row + 1, grid.rows - 1);
    at.h00 = grid.node(at.column, at.row);
    at.h10 = grid.node(c1, at.row);
    at.h01 = grid.node(at.column, r1);
    at.h11 = grid.node(c1, r1);
    if (std::isnan(at.h00) || std::isnan(at.h10) || std::isnan(at.h01) || std::isnan(at.h11)) return std::nullopt;
    return at;
}

}  // namespace

std::optional<double> bilinearHeight(const HeightGrid &grid, const MapPoint &p) {
    auto at = cellAt(grid, p);
    if (!at) return std::nullopt;
    double south = at->h00 + at->fx * (double(at->h10) - at->h00);
    double north = at->h01 + at->fx * (double(at->h11) - at->h01);
    return south + at->fy * (north - south);
}

std::optional<double> surfaceHeight(const HeightGrid &grid, const MapPoint &p) {
    auto at = cellAt(grid, p);
    if (!at) return std::nullopt;
    if (at->fx >= at->fy)  // the south-east triangle
        return at->h00 + at->fx * (double(at->h10) - at->h00) + at->fy * (double(at->h11) - at->h10);
    return at->h00 + at->fy * (double(at->h01) - at->h00) + at->fx * (double(at->h11) - at->h01);
}

std::optional<double> slopeDegrees(const HeightGrid &grid, const MapPoint &p) {
    auto at = cellAt(grid, p);
    if (!at || grid.spacing <= 0) return std::nullopt;
    double east = (1 - at->fy) * (double(at->h10) - at->h00) + at->fy * (double(at->h11) - at->h01);
    double north = (1 - at->fx) * (double(at->h01) - at->h00) + at->fx * (double(at->h11) - at->h10);
    return std::atan(std::hypot(east, north) / grid.spacing) * 180 / M_PI;
}

}  // namespace veduta
