// Writing a CityData file (docs/citydata.md) that readCityData reads back as it was: what
// `veduta generate` writes of a grown city, for a <city> to load and a person to edit.
#pragma once

#include <filesystem>
#include <string>

#include "city/city_data.h"

namespace veduta {

struct CityDataWriting {
    MapOffset offset;     // added to every point's e and n
    std::string comment;  // written as an XML comment at the top: how the file was made
};

// The file's text. Block and lot corners are the city's points where a point has their exact
// coordinates and height, else new points numbered after the city's; local coordinates exact,
// map coordinates (an offset) to 0.1 mm; settings in name order; rule files relative to
// `folder` (the file's) where they lie under it, else absolute.
std::string cityDataXml(const CityData &city, const CityDataWriting &writing, const std::filesystem::path &folder);
// Written atomically (core/atomic_file.h). Throws std::runtime_error naming the file.
void writeCityData(const CityData &city, const CityDataWriting &writing, const std::filesystem::path &file);

}  // namespace veduta
