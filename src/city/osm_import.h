// OpenStreetMap data as a city (issue 7, item 5): an .osm XML file read with GDAL's OSM driver
// becomes the CityData that readCityData gives for Bilke's scene files (Bilke 2009, §2.1.2):
// highways are streets, landuse=residential areas blocks, buildings lots with their tags as
// building settings. docs/osm.md has the mapping and the choices.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "city/city_data.h"
#include "geodesy/georeference.h"

namespace veduta {

struct OsmImportOptions {
    // The scene's georeference: points are projected into its CRS and made local to its origin
    // (geo/map_projection.h), grid north up, as the landscape's. Unset: the tangent plane below.
    std::optional<Georeference> georeference;
    // Without a georeference, the point (WGS 84 degrees) that becomes e = n = 0; unset: the
    // centre of the bounding box of everything imported.
    std::optional<GeographicPoint> origin;
    // The width of highways of a class without a width of its own (CityData::streetWidth).
    float defaultStreetWidth = 5;
    std::vector<std::filesystem::path> ruleFiles;  // CityData::ruleFiles: OSM names none
};

// Points lie in the scene's frame (with a georeference), else in the local east/north plane at
// the origin (GeographicLib's LocalCartesian, true north up); u = 0.
// Ways that cannot be used are skipped with a warning "file: way <id>: message" in
// CityData::warnings; a file that GDAL cannot read throws InputError naming it.
CityData importOsm(const std::filesystem::path &file, const OsmImportOptions &options);

}  // namespace veduta
