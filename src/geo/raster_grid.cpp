#include "geo/raster_grid.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include "core/error.h"
#include "io/gdal_guard.h"
#include "io/gdal_messages.h"

namespace veduta {

namespace {

// Heights read as float32 that are no heights: infinities, or values beyond any on Earth
// (NaN is no data, and stays).
void checkHeights(const HeightGrid &grid, const FileLoc &loc) {
    for (size_t i = 0; i < grid.heights.size(); ++i) {
        float h = grid.heights[i];
        if (std::isnan(h) || std::abs(h) <= kMaxHeight) continue;
        size_t column = i % size_t(grid.columns), row = i / size_t(grid.columns);
        throw InputError(loc,
                         fmt::format("the height {} at pixel ({}, {}) lies beyond any on Earth (±{} m)", h, column,
                                     size_t(grid.rows) - 1 - row, kMaxHeight));
    }
}

// A text raster holds at least two characters per height (a digit and a separator): one whose
// header promises more heights than that is refused before the heights are allocated (a
// 60-byte ASC header would otherwise claim gigabytes).
void checkTextSize(GDALDataset &dataset, const std::filesystem::path &path, const HeightGrid &grid,
                   const FileLoc &loc) {
    std::string driver = dataset.GetDriver() ? dataset.GetDriver()->GetDescription() : "";
    if (driver != "AAIGrid" && driver != "GRASSASCIIGrid" && driver != "XYZ") return;
    std::error_code error;
    double bytes = double(std::filesystem::file_size(path, error));
    double heights = double(grid.columns) * double(grid.rows);
    if (!error && heights > bytes / 2)
        throw InputError(loc,
                         fmt::format("the header promises {} × {} heights, more than the file's {:.0f} bytes can "
                                     "hold",
                                     grid.columns, grid.rows, bytes));
}

// The EPSG code of the raster's CRS, 0 when it has none or GDAL finds no EPSG code for it
// (an ESRI .prj names its CRS by a WKT without authority).
int epsgOf(const GDALDataset &dataset) {
    const OGRSpatialReference *crs = dataset.GetSpatialRef();
    if (!crs || crs->IsEmpty()) return 0;
    std::unique_ptr<OGRSpatialReference> copy(crs->Clone());
    auto code = [&]() -> int {
        const char *authority = copy->GetAuthorityName(nullptr);
        const char *value = copy->GetAuthorityCode(nullptr);
        return authority && value && std::strcmp(authority, "EPSG") == 0 ? std::atoi(value) : 0;
    };
    if (int epsg = code()) return epsg;
    if (copy->AutoIdentifyEPSG() == OGRERR_NONE)
        if (int epsg = code()) return epsg;
    int count = 0;
    int *confidences = nullptr;
    OGRSpatialReferenceH *matches = copy->FindMatches(nullptr, &count, &confidences);
    int epsg = 0;
    if (count > 0 && confidences[0] >= 90) {
        copy.reset(OGRSpatialReference::FromHandle(matches[0])->Clone());
        epsg = code();
    }
    OSRFreeSRSArray(matches);
    CPLFree(confidences);
    return epsg;
}

void flipRows(HeightGrid &grid) {
    size_t width = size_t(grid.columns);
    for (int low = 0, high = grid.rows - 1; low < high; ++low, --high) {
        std::swap_ranges(grid.heights.begin() + ptrdiff_t(low * width),
                         grid.heights.begin() + ptrdiff_t((low + 1) * width),
                         grid.heights.begin() + ptrdiff_t(high * width));
    }
}

// The raster warped into EPSG `epsg` as gdalwarp would (see readRasterGrid), a virtual
// dataset that reads `source` while it lives.
GDALDatasetUniquePtr warpedInto(GDALDataset &source, int epsg, const FileLoc &loc, const GdalMessages &messages) {
    std::string target = fmt::format("EPSG:{}", epsg);
    const char *arguments[] = {"-of", "VRT",     "-t_srs",     target.c_str(), "-r",   "bilinear",
                               "-ot", "Float32", "-dstnodata", "nan",          nullptr};
    GDALWarpAppOptions *options = GDALWarpAppOptionsNew(const_cast<char **>(arguments), nullptr);
    GDALDatasetH sourceHandle = GDALDataset::ToHandle(&source);
    int usageError = 0;
    GDALDatasetH warped = GDALWarp("", nullptr, 1, &sourceHandle, options, &usageError);
    GDALWarpAppOptionsFree(options);
    if (!warped) throw InputError(loc, fmt::format("GDAL cannot warp the DGM into {}{}", target, messages.detail()));
    return GDALDatasetUniquePtr(GDALDataset::FromHandle(warped));
}

bool isGeographic(const GDALDataset &dataset) {
    const OGRSpatialReference *crs = dataset.GetSpatialRef();
    return crs && !crs->IsEmpty() && crs->IsGeographic();
}

}  // namespace

Dgm readRasterGrid(const std::filesystem::path &path, int warpTo) {
    checkFileForGdal(path);
    registerGdalDrivers();
    FileLoc loc{path.string(), 0, 0};
    GdalMessages messages;
    GdalDeadline deadline(path);
    GDALDatasetUniquePtr file(
        GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
    if (!file) throw InputError(loc, "GDAL cannot read this as a raster" + messages.detail());
    if (file->GetRasterCount() < 1) throw InputError(loc, "the raster has no band");
    int warpedFrom = 0;
    if (warpTo != 0 && isGeographic(*file)) {
        warpedFrom = epsgOf(*file);
        if (warpedFrom == 0)
            throw InputError(loc, "the DGM is in a geographic CRS without an EPSG code; veduta warps only known CRSs");
    }
    // Declared after `file`, which it reads, so that it is closed first.
    GDALDatasetUniquePtr warped = warpedFrom ? warpedInto(*file, warpTo, loc, messages) : nullptr;
    GDALDataset *dataset = warped ? warped.get() : file.get();

    double transform[6] = {0, 1, 0, 0, 0, 1};
    if (dataset->GetGeoTransform(transform) != CE_None)
        throw InputError(loc, "the raster has no georeference (no geotransform)");
    if (transform[2] != 0 || transform[4] != 0)
        throw InputError(loc, "the raster is rotated; only north-up rasters are read");
    double dx = transform[1], dy = transform[5];
    if (!(dx > 0)) throw InputError(loc, fmt::format("the pixel width is {}; it must be positive", dx));
    if (!(std::abs(dx - std::abs(dy)) < 1e-6 * dx))
        throw InputError(
            loc, fmt::format("the pixels are not square ({} m × {} m); a DGM needs one spacing", dx, std::abs(dy)));

    Dgm dgm;
    HeightGrid &grid = dgm.grid;
    grid.columns = dataset->GetRasterXSize();
    grid.rows = dataset->GetRasterYSize();
    if (double(grid.columns) * grid.rows > kMaxGridNodes)
        throw InputError(loc,
                         fmt::format("the raster has {} × {} pixels, more than the {:.0e} a DGM may have", grid.columns,
                                     grid.rows, kMaxGridNodes));
    checkTextSize(*dataset, path, grid, loc);
    grid.spacing = dx;
    grid.west = transform[0] + 0.5 * dx;
    // Row 0 of a north-up raster is its north edge; the grid counts from the south.
    grid.south = dy < 0 ? transform[3] + (grid.rows - 0.5) * dy : transform[3] + 0.5 * dy;

    GDALRasterBand *band = dataset->GetRasterBand(1);
    grid.heights.resize(size_t(grid.columns) * size_t(grid.rows));
    if (band->RasterIO(GF_Read, 0, 0, grid.columns, grid.rows, grid.heights.data(), grid.columns, grid.rows,
                       GDT_Float32, 0, 0, nullptr) != CE_None)
        throw InputError(loc, "GDAL cannot read the heights" + messages.detail());
    if (dy < 0) flipRows(grid);

    int hasNoData = 0;
    double noData = band->GetNoDataValue(&hasNoData);
    if (hasNoData) {
        // Compared as float32, the type the heights were read as.
        float marker = float(noData);
        for (float &h : grid.heights)
            if (h == marker) h = std::numeric_limits<float>::quiet_NaN();
    }
    checkHeights(grid, loc);
    dgm.epsg = epsgOf(*dataset);
    dgm.warpedFrom = warpedFrom;
    return dgm;
}

}  // namespace veduta
