// A city as GIS layers for QGIS and its kin: streets as lines, blocks and lots as polygons,
// written by GDAL (GeoJSON or GeoPackage) in map coordinates of the city's CRS. What
// `veduta generate --geojson/--gpkg` writes; docs/generate.md lists the layers and fields.
#pragma once

#include <filesystem>
#include <vector>

#include "city/city_data.h"

namespace veduta {

struct CityLayersFrame {
    MapOffset offset;  // added to every coordinate
    int epsg = 0;      // the CRS the layers declare; 0: none (local metres)
};

// The files a layer set is written to: GeoJSON holds one layer per file, so a folder gets
// streets.geojson, blocks.geojson and lots.geojson; a GeoPackage (.gpkg) holds all three.
std::vector<std::filesystem::path> cityLayerFiles(const std::filesystem::path &target);

// Writes the layers "streets" (id, start, end: point ids; width), "blocks" (id: its identity;
// area) and "lots" (block: its block's identity, lot: its place in the block, area; the
// streetEdges as a field street_edges of edge numbers). Each file is written atomically.
// Throws std::runtime_error naming the file and what GDAL said.
void writeCityLayers(const CityData &city, const CityLayersFrame &frame, const std::filesystem::path &target);

}  // namespace veduta
