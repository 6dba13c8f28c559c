// Building settings as a description holds them: Bilke's <BuildingSettings> name/value
// pairs (Bilke 2009, §1), read from scene files, CityData files and rule files alike. What
// they mean to a building is src/city/building_settings.h.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>

#include "core/error.h"

namespace veduta {

// A setting given in a <BuildingSettings> element: the element's name and its text, a number
// or a string.
struct SettingValue {
    std::string text;
    std::optional<float> number;
    FileLoc loc;
};

using SettingsMap = std::unordered_map<std::string, SettingValue>;

// A setting's value from its text: a number when the whole text reads as one.
SettingValue settingValue(std::string text, const FileLoc &loc);

class XmlElement;
// Bilke's <BuildingSettings>: each child element's name is a setting and its text the value,
// a number or a string. A setting given twice is an error.
SettingsMap readBuildingSettings(const XmlElement &element);

}  // namespace veduta
