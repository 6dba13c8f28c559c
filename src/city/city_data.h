// Bilke's CityData scene files (Bilke 2009, §2.1.2, Listing 2.1): points, streets, blocks,
// lots with their street edges, building settings at three levels and the rule files. Read and
// checked here; nothing is generated. docs/citydata.md documents the format and the checks.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "city/building_settings.h"
#include "core/error.h"
#include "core/vecmath.h"

namespace veduta {

// How far from the scene origin a city's points may lie (metres, in each of e and n): its
// streets, lots and buildings are built in single precision, which holds 8 mm there and a
// metre at 10,000 km, where street ribbons and Booleans fall apart.
inline constexpr double kMaxCityReach = 1e5;

struct CityPoint {
    uint32_t id = 0;
    // Metres east, north and up: the file's own, or, read through a MapProjection, metres
    // from the scene origin (still double, so no float ever holds a map coordinate).
    double e = 0, n = 0, u = 0;
    FileLoc loc;
};

struct CityStreet {
    uint32_t id = 0;
    uint32_t start = 0, end = 0;  // indices into CityData::points
    std::optional<float> width;   // unset: the network's <Width>
    FileLoc loc;
};

// A lot: counter-clockwise, with the edges on a street flagged (edge i runs from point i to i+1).
struct CityLot {
    std::vector<Vec2f> points;
    std::vector<bool> streetEdges;
    float base = 0;  // the points' common u
    SettingsMap settings;
    FileLoc loc;
    // Its identity in its source, whatever else the file holds: a hash of the ids of its points
    // in file order (CityData) or of its OpenStreetMap way or relation and part.
    uint32_t sourceId = 0;
};

struct CityBlock {
    std::vector<Vec2f> points;  // counter-clockwise
    float base = 0;
    std::vector<CityLot> lots;
    SettingsMap settings;
    FileLoc loc;
    uint32_t sourceId = 0;  // as a lot's: what its lots are cut with when it has none of its own
};

struct CityData {
    std::vector<CityPoint> points;
    std::vector<CityStreet> streets;
    float streetWidth = 5;  // <StreetNetwork><Width>, for streets without their own
    std::vector<CityBlock> blocks;
    SettingsMap settings;
    std::vector<std::filesystem::path> ruleFiles;  // resolved against the file's folder
    std::vector<std::string> warnings;             // "file:line:col: message"
};

// Where the local frame's origin lies in a projected CRS, for writing a city in map
// coordinates: a point's easting is east + e, its northing north + n.
struct MapOffset {
    double east = 0, north = 0;
};

class MapProjection;

// With a projection, the points' e and n are eastings and northings (or longitudes and
// latitudes) of its source CRS, placed in the scene's frame; without, local metres as they are.
CityData readCityData(const std::filesystem::path &file, const MapProjection *projection = nullptr);
// The same for text in memory: `name` is what messages call it; rule files resolve against
// `baseDirectory`.
CityData parseCityData(std::string xml, std::string name, const std::filesystem::path &baseDirectory,
                       const MapProjection *projection = nullptr);

// Bilke's precedence: lot > block > city > the rule file's settings > built-in defaults.
// The stack points at the maps, which must outlive it.
SettingsStack settingsFor(const CityData &city, const CityBlock &block, const CityLot *lot,
                          const SettingsMap &ruleFileSettings);

}  // namespace veduta
