#include "city/building_settings.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/random_streams.h"
#include "io/xml_reader.h"

namespace veduta {

const SettingValue *SettingsStack::find(const std::string &name) const {
    for (const SettingsMap *layer : layers_) {
        auto it = layer->find(name);
        if (it != layer->end()) return &it->second;
    }
    return nullptr;
}

std::optional<float> SettingsStack::number(const std::string &name) const {
    const SettingValue *value = find(name);
    if (!value) return std::nullopt;
    if (!value->number)
        throw InputError(value->loc, fmt::format("setting {} must be a number, not '{}'", name, value->text));
    return value->number;
}

std::optional<std::string> SettingsStack::text(const std::string &name) const {
    const SettingValue *value = find(name);
    return value ? std::optional(value->text) : std::nullopt;
}

const SettingsMap &defaultBuildingSettings() {
    static const SettingsMap defaults = [] {
        SettingsMap map;
        FileLoc loc{"<built-in defaults>", 0, 0};
        auto set = [&](const char *name, float value) {
            map[name] = SettingValue{fmt::format("{}", value), value, loc};
        };
        set("BuildingHeight", 15);
        set("BuildingHeightVar", 0);
        set("FloorHeight", 3);
        set("FloorHeightVar", 0);
        set("RoofHeight", 4);
        set("RoofHeightVar", 0);
        return map;
    }();
    return defaults;
}

namespace {

// A setting that must be positive, or zero or more; an error at the setting when it is not.
float checkedNumber(const SettingsStack &settings, const std::string &name, bool positive) {
    float value = settings.number(name).value_or(0);
    if (positive ? value > 0 : value >= 0) return value;
    const SettingValue *given = settings.find(name);
    throw InputError(given ? given->loc : FileLoc{},
                     fmt::format("{} must be {}, not {}", name, positive ? "positive" : "zero or more", value));
}

float randomised(const SettingsStack &settings, const std::string &name, bool positive, uint32_t seed,
                 uint32_t buildingId, uint32_t which) {
    float base = checkedNumber(settings, name, positive);
    float deviation = checkedNumber(settings, name + "Var", false);
    float u = bitsToUnitFloat(hashValues({seed, buildingId, streamTag(RandomStream::BuildingHeights), which}));
    // A deviation larger than the value must not turn a storey or a building upside down.
    return std::max(base + (2 * u - 1) * deviation, 0.1f * base);
}

}  // namespace

BuildingHeights randomiseHeights(const SettingsStack &settings, uint32_t seed, uint32_t buildingId) {
    return {randomised(settings, "BuildingHeight", true, seed, buildingId, 0),
            randomised(settings, "FloorHeight", true, seed, buildingId, 1),
            randomised(settings, "RoofHeight", false, seed, buildingId, 2)};
}

BuildingProperties::BuildingProperties(const SettingsStack &settings, const BuildingHeights &heights) :
    settings_(&settings), heights_(heights) {}

std::optional<float> BuildingProperties::number(const std::string &name) const {
    if (name == "BuildingHeight" || name == "ActualBuildingHeight") return heights_.building;
    if (name == "FloorHeight" || name == "ActualFloorHeight") return heights_.floor;
    if (name == "RoofHeight" || name == "ActualRoofHeight") return heights_.roof;
    return settings_->number(name);
}

}  // namespace veduta
