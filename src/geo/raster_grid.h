// DGM rasters through GDAL: ESRI ASCII grids, GeoTIFF and whatever else GDAL reads.
#pragma once

#include <filesystem>

#include "geo/dgm_file.h"

namespace veduta {

// Band 1 of a north-up raster, pixel centres as nodes (GDAL's geotransform: the node of
// column c and raster row r lies at origin + (c + ½, r + ½) · pixel size; an ESRI ASCII
// grid's xllcorner + cellsize/2). Its no-data value becomes NaN. Pixels must be square to
// within 1e-6 of their width (the width is the spacing); rotated rasters are refused.
// A raster in a geographic CRS (SRTM .hgt, most global DEMs) is warped into `warpTo` when it
// is not 0, as `gdalwarp -t_srs EPSG:<warpTo> -r bilinear -ot Float32` does it, through a
// virtual (VRT) dataset: square nodes of about the source's resolution, NaN outside the
// source; Dgm::warpedFrom then names the source's EPSG code.
Dgm readRasterGrid(const std::filesystem::path &file, int warpTo = 0);

}  // namespace veduta
