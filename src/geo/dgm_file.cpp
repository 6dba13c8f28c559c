#include "geo/dgm_file.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"
#include "geo/no_data_fill.h"
#include "geo/raster_grid.h"
#include "geo/xyz_grid.h"

namespace veduta {

namespace {

// Tiles must agree in spacing, and their nodes must line up, to this fraction of a spacing.
constexpr double kAlignTolerance = 0.01;

struct Tile {
    std::filesystem::path file;
    Dgm dgm;
    int64_t column = 0, row = 0;  // of its south-west node in the grid of the first tile
};

// Where `tile`'s south-west node lies in the node grid of `first`; checks spacing and alignment.
void placeTile(const Tile &first, Tile &tile, int64_t mosaicNodes) {
    const HeightGrid &a = first.dgm.grid, &b = tile.dgm.grid;
    FileLoc loc{tile.file.string(), 0, 0};
    // A spacing error that would move the far nodes of the mosaic by a noticeable part of a spacing.
    if (std::abs(a.spacing - b.spacing) * double(mosaicNodes) > kAlignTolerance * a.spacing)
        throw InputError(loc,
                         fmt::format("the grid spacing {:.9g} m differs from the {:.9g} m of {}", b.spacing, a.spacing,
                                     first.file.string()));
    double column = (b.west - a.west) / a.spacing, row = (b.south - a.south) / a.spacing;
    tile.column = int64_t(std::llround(column));
    tile.row = int64_t(std::llround(row));
    if (std::abs(column - double(tile.column)) > kAlignTolerance || std::abs(row - double(tile.row)) > kAlignTolerance)
        throw InputError(
            loc,
            fmt::format("the nodes are off the nodes of {} by {:.4f} m east, {:.4f} m north", first.file.string(),
                        (column - double(tile.column)) * a.spacing, (row - double(tile.row)) * a.spacing));
    if (first.dgm.epsg && tile.dgm.epsg && first.dgm.epsg != tile.dgm.epsg)
        throw InputError(loc,
                         fmt::format("the CRS is EPSG:{}, but {} is in EPSG:{}", tile.dgm.epsg, first.file.string(),
                                     first.dgm.epsg));
}

Dgm mosaic(std::vector<Tile> &tiles, std::vector<std::string> &warnings) {
    Tile &first = tiles.front();
    int64_t largest = 0;
    for (const Tile &t : tiles) largest = std::max<int64_t>(largest, std::max(t.dgm.grid.columns, t.dgm.grid.rows));
    for (Tile &t : tiles) placeTile(first, t, largest * int64_t(tiles.size()));

    int64_t west = 0, south = 0, east = 0, north = 0;  // node indices in the first tile's grid
    for (const Tile &t : tiles) {
        west = std::min(west, t.column), south = std::min(south, t.row);
        east = std::max(east, t.column + t.dgm.grid.columns - 1), north = std::max(north, t.row + t.dgm.grid.rows - 1);
    }
    double columns = double(east - west + 1), rows = double(north - south + 1);
    if (columns * rows > kMaxGridNodes)
        throw InputError({first.file.string(), 0, 0},
                         fmt::format("the tiles span {} × {} nodes, more than the {:.0e} a DGM may have", columns, rows,
                                     kMaxGridNodes));
    Dgm result;
    HeightGrid &grid = result.grid;
    grid.spacing = first.dgm.grid.spacing;
    grid.west = first.dgm.grid.west + double(west) * grid.spacing;
    grid.south = first.dgm.grid.south + double(south) * grid.spacing;
    grid.columns = int(columns);
    grid.rows = int(rows);
    grid.heights.assign(size_t(grid.columns) * size_t(grid.rows), std::numeric_limits<float>::quiet_NaN());

    for (const Tile &t : tiles) {
        if (!result.epsg) result.epsg = t.dgm.epsg;
        size_t disagreeing = 0;
        double largestDifference = 0;
        const HeightGrid &g = t.dgm.grid;
        for (int r = 0; r < g.rows; ++r) {
            for (int c = 0; c < g.columns; ++c) {
                float h = g.node(c, r);
                if (std::isnan(h)) continue;
                float &target = grid.node(int(t.column - west) + c, int(t.row - south) + r);
                if (std::isnan(target)) {
                    target = h;
                } else if (target != h) {
                    ++disagreeing;
                    largestDifference = std::max(largestDifference, std::abs(double(target) - h));
                }
            }
        }
        if (disagreeing)
            warnings.push_back(
                fmt::format("{}: {} nodes where it overlaps earlier tiles differ from them by up to "
                            "{:.3f} m; the earlier tiles' heights are kept",
                            t.file.string(), disagreeing, largestDifference));
    }
    return result;
}

void applyPolicy(Dgm &dgm, NoDataPolicy noData, const std::filesystem::path &first,
                 std::vector<std::string> &warnings) {
    size_t missing = countNoData(dgm.grid);
    if (missing == dgm.grid.heights.size()) throw InputError({first.string(), 0, 0}, "the DGM has no height at all");
    if (missing == 0) return;
    const size_t nodes = dgm.grid.heights.size();
    if (noData.fillDistance == 0) {
        warnings.push_back(
            fmt::format("{}: {} of {} DGM nodes have no data; the terrain leaves out the cells around them",
                        first.string(), missing, nodes));
        return;
    }
    NoDataFill fill = fillNoData(dgm.grid, noData.fillDistance);
    if (fill.cut == 0) {
        warnings.push_back(fmt::format("{}: {} of {} DGM nodes had no data and were filled from their neighbours",
                                       first.string(), missing, nodes));
        return;
    }
    std::string filled = fill.filled == 0 ? ""
                                          : fmt::format(
                                                "{} in holes within {} nodes of a height were filled from "
                                                "their neighbours, ",
                                                fill.filled, noData.fillDistance);
    warnings.push_back(
        fmt::format("{}: {} of {} DGM nodes had no data: {}{} in {} hole{} reaching farther than {} "
                    "nodes from any height are cut, not made up (the terrain leaves out the cells "
                    "around them; <landscape fill_distance> fills farther)",
                    first.string(), missing, nodes, filled, fill.cut, fill.cutHoles, fill.cutHoles == 1 ? "" : "s",
                    noData.fillDistance));
}

}  // namespace

Dgm readDgm(const std::filesystem::path &file, int warpTo) {
    checkInputFile(file);
    if (looksLikeXyz(file)) return Dgm{readXyzGrid(file), 0};
    return readRasterGrid(file, warpTo);
}

Dgm readDgmTiles(const std::vector<std::filesystem::path> &files, NoDataPolicy noData,
                 std::vector<std::string> &warnings, int warpTo) {
    if (files.empty()) throw InputError({}, "no DGM files given");
    std::vector<Tile> tiles;
    tiles.reserve(files.size());
    for (const auto &file : files) {
        tiles.push_back(Tile{file, readDgm(file, warpTo), 0, 0});
        const Dgm &dgm = tiles.back().dgm;
        if (dgm.warpedFrom != 0)
            warnings.push_back(fmt::format(
                "{}: the DGM is in EPSG:{}, a geographic CRS; GDAL warped it into "
                "EPSG:{} (bilinear): {} × {} nodes {:.3f} m apart",
                file.string(), dgm.warpedFrom, dgm.epsg, dgm.grid.columns, dgm.grid.rows, dgm.grid.spacing));
    }
    Dgm result = tiles.size() == 1 ? std::move(tiles.front().dgm) : mosaic(tiles, warnings);
    applyPolicy(result, noData, files.front(), warnings);
    return result;
}

}  // namespace veduta
