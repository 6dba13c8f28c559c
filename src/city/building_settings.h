// Building settings (Bilke's BuildingSettings variables) and their precedence: lot > block >
// city > rule file > defaults (Bilke 2009, §2). A building resolves them once into the
// properties its rules read, with its heights randomised within their `…Var` deviations.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "city/rules.h"
#include "description/settings_map.h"

namespace veduta {

// Layers looked up front to back: the first layer that defines a name wins. The layers are
// pointers: the maps must outlive the stack.
class SettingsStack {
  public:
    SettingsStack() = default;
    explicit SettingsStack(std::vector<const SettingsMap *> layers) : layers_(std::move(layers)) {}

    const SettingValue *find(const std::string &name) const;
    // The value as a number; an InputError at the setting when it is not one.
    std::optional<float> number(const std::string &name) const;
    std::optional<std::string> text(const std::string &name) const;

  private:
    std::vector<const SettingsMap *> layers_;
};

// Bilke's defaults (L1245): BuildingHeight 15, FloorHeight 3, RoofHeight 4 metres.
const SettingsMap &defaultBuildingSettings();

// One building's heights after randomisation: each is its setting plus a deviation drawn
// uniformly from [-Var, +Var] (the thesis names no distribution), never below a tenth of the
// setting. BuildingHeight and FloorHeight must be positive, RoofHeight (0: a flat roof) and the
// deviations zero or more; InputError at the setting otherwise.
struct BuildingHeights {
    float building = 15;  // the walls: eaves above the footprint's base
    float floor = 3;
    float roof = 4;
};
BuildingHeights randomiseHeights(const SettingsStack &, uint32_t seed, uint32_t buildingId);

// What a building's rules read as `property`: its settings, except that BuildingHeight,
// FloorHeight and RoofHeight (and Bilke's Actual… names for them) give the randomised values.
class BuildingProperties {
  public:
    // Keeps a pointer to `settings`, which must outlive it.
    BuildingProperties(const SettingsStack &settings, const BuildingHeights &heights);
    BuildingProperties(SettingsStack &&, const BuildingHeights &) = delete;
    std::optional<float> number(const std::string &name) const;

  private:
    const SettingsStack *settings_;
    BuildingHeights heights_;
};

}  // namespace veduta
