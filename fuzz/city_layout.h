// What a city's data goes through before its buildings (city/generate_city.h): the street
// network and its surface, and every block's lots. The CityData and OSM targets run it on
// what their readers return, since the street booleans are where real data crashed veduta.
#pragma once

#include "city/city_data.h"
#include "city/generate_city.h"
#include "city/street_geometry.h"

namespace veduta::fuzz {

inline void layOutCity(const CityData &data) {
    StreetNetwork streets = streetNetworkOf(data);
    streetGeometry(streets);
    const SettingsMap noRuleFileSettings;
    for (const CityBlock &block : data.blocks) {
        lotsOf(block, streets, settingsFor(data, block, nullptr, noRuleFileSettings), 1);
    }
}

}  // namespace veduta::fuzz
