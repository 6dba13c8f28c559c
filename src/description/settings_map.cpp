#include "description/settings_map.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "io/xml_reader.h"

namespace veduta {

SettingValue settingValue(std::string text, const FileLoc &loc) {
    SettingValue value{std::move(text), std::nullopt, loc};
    float number = 0;
    const char *first = value.text.data(), *last = first + value.text.size();
    auto [end, error] = std::from_chars(first, last, number);
    if (error == std::errc() && end == last && std::isfinite(number)) value.number = number;
    return value;
}

SettingsMap readBuildingSettings(const XmlElement &element) {
    element.checkAllRead();
    SettingsMap settings;
    for (const XmlElement &child : element.children()) {
        child.checkLeaf();
        auto [it, fresh] = settings.emplace(std::string(child.name()), settingValue(child.text(), child.textLoc()));
        if (!fresh)
            child.fail(
                fmt::format("the setting {} is given twice (first at {})", child.name(), it->second.loc.toString()));
    }
    return settings;
}

}  // namespace veduta
