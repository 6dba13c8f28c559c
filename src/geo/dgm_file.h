// Reading DGMs (digital terrain models): ASCII XYZ files with our own parser, and ESRI ASCII
// grids, GeoTIFF and every other raster GDAL reads through GDAL, each into a HeightGrid; and
// several tiles of one survey put together. See docs/terrain.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "geo/height_grid.h"

namespace veduta {

// A DGM as read: the grid and the EPSG code of its CRS, 0 when the file names none (XYZ files
// never do) or GDAL cannot match its CRS to an EPSG code.
struct Dgm {
    HeightGrid grid;
    int epsg = 0;
    int warpedFrom = 0;  // the EPSG code of the geographic CRS the file was warped from, or 0
};

// What to do with nodes that have no data (NaN) after the tiles are put together: the holes
// within `fillDistance` rings of a height are filled from their neighbours (fillNoData,
// no_data_fill.h); the rest stay NaN, and the terrain mesh leaves out the cells around them.
struct NoDataPolicy {
    int fillDistance = 0;  // 0: fill nothing (nodata="cut")
};

// One file. XYZ is recognised by its content (the first line that is not blank or a comment
// holds three numbers: xyz_grid.h); anything else goes to GDAL, whose pixel centres become
// the nodes. Nodes without data stay NaN. A geographic raster is warped into `warpTo` unless
// it is 0 (raster_grid.h). Throws InputError.
Dgm readDgm(const std::filesystem::path &file, int warpTo = 0);

// Several tiles of one DGM as one grid over their bounding box. The tiles must have the same
// spacing and their nodes must line up (an error names both files); where tiles overlap the
// first in `files` wins, and a warning counts the nodes where a later tile disagrees.
// Then `noData` decides about the nodes no tile covers or has data for (a warning counts
// what was filled and what was cut). Tiles with two different EPSG codes are an error; the
// result has the one named. Geographic tiles are warped into `warpTo` (unless 0), each with a
// warning that says so.
Dgm readDgmTiles(const std::vector<std::filesystem::path> &files, NoDataPolicy noData,
                 std::vector<std::string> &warnings, int warpTo = 0);

}  // namespace veduta
