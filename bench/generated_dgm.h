// The benchmarks' generated DGM: smooth hills with value noise of 4 m at 40 m and 0.5 m at 5 m
// on top, a pure function of the node's place, so a DGM10 is rough at its own resolution; and
// its float32 GeoTIFF in ETRS89 / UTM 32N, as a surveying office delivers one. bench_terrain
// meshes it (1 km² at 1 m, 34 × 20 km at 10 m); bench_dgm_geotiff writes the 34 × 20 km one for
// bench/big_landscape.sh.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include "core/hash.h"
#include "geo/height_grid.h"

namespace veduta {

inline constexpr uint32_t kGeneratedDgmSeed = 2024;
// The south-west node of every generated DGM (EPSG:25832).
inline constexpr double kGeneratedDgmWest = 400000, kGeneratedDgmSouth = 5600000;

// Value noise in −1…1 over a lattice of `cell` metres, smoothly interpolated.
inline double generatedValueNoise(double x, double y, double cell, uint32_t octave) {
    double fx = x / cell, fy = y / cell;
    double ix = std::floor(fx), iy = std::floor(fy);
    double tx = fx - ix, ty = fy - iy;
    tx = tx * tx * (3 - 2 * tx), ty = ty * ty * (3 - 2 * ty);
    auto lattice = [&](double i, double j) {
        return 2 *
            bitsToUnitFloat(hashValues({kGeneratedDgmSeed, octave, uint32_t(int64_t(i)), uint32_t(int64_t(j))})) -
            1;
    };
    double south = lattice(ix, iy) + tx * (lattice(ix + 1, iy) - lattice(ix, iy));
    double north = lattice(ix, iy + 1) + tx * (lattice(ix + 1, iy + 1) - lattice(ix, iy + 1));
    return south + ty * (north - south);
}

// The height at (x, y) metres east and north of the south-west node: 250 m ± 85 m.
inline float generatedTerrainHeight(double x, double y) {
    return float(250 + 60 * std::sin(x / 900) * std::cos(y / 700) + 20 * std::sin((x + 2 * y) / 310) +
                 4 * generatedValueNoise(x, y, 40, 1) + 0.5 * generatedValueNoise(x, y, 5, 2));
}

inline HeightGrid generatedDgm(int columns, int rows, double spacing) {
    HeightGrid grid;
    grid.west = kGeneratedDgmWest;
    grid.south = kGeneratedDgmSouth;
    grid.spacing = spacing;
    grid.columns = columns;
    grid.rows = rows;
    grid.heights.resize(size_t(columns) * size_t(rows));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) grid.node(c, r) = generatedTerrainHeight(c * spacing, r * spacing);
    return grid;
}

// The terrain issue's big DGM: 34 × 20 km at 10 m, 3401 × 2001 nodes (a float32 GeoTIFF of 27 MB).
inline HeightGrid generatedDgm34x20km() { return generatedDgm(3401, 2001, 10); }

// The grid as a north-up float32 GeoTIFF in EPSG:25832, pixel centres on the nodes.
inline void writeGeoTiff(const HeightGrid &grid, const std::filesystem::path &file) {
    GDALAllRegister();
    GDALDriver *driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    GDALDatasetUniquePtr out(driver->Create(file.c_str(), grid.columns, grid.rows, 1, GDT_Float32, nullptr));
    if (!out) throw std::runtime_error("cannot create " + file.string());
    double transform[6] = {
        grid.west - grid.spacing / 2, grid.spacing, 0, grid.north() + grid.spacing / 2, 0, -grid.spacing};
    out->SetGeoTransform(transform);
    OGRSpatialReference crs;
    crs.importFromEPSG(25832);
    out->SetSpatialRef(&crs);
    std::vector<float> northFirst;
    northFirst.reserve(grid.heights.size());
    for (int r = grid.rows - 1; r >= 0; --r)
        northFirst.insert(northFirst.end(), grid.heights.begin() + ptrdiff_t(size_t(r) * size_t(grid.columns)),
                          grid.heights.begin() + ptrdiff_t(size_t(r + 1) * size_t(grid.columns)));
    if (out->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, grid.columns, grid.rows, northFirst.data(), grid.columns,
                                        grid.rows, GDT_Float32, 0, 0, nullptr) != CE_None)
        throw std::runtime_error("cannot write " + file.string());
}

}  // namespace veduta
