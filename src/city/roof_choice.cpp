#include "city/roof_choice.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "city/roofs.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

constexpr float kSteepestDerivedPitch = 89;  // degrees

std::string roofTypeNames() {
    std::string names;
    for (RoofType type : kRoofTypes) names += fmt::format("{}{}", names.empty() ? "" : ", ", roofTypeName(type));
    return names;
}

// RoofType: one name, or several separated by spaces or commas, of which each building takes
// one at random. Unset: Bilke's choice.
RoofType chosenType(const Footprint &footprint, const SettingsStack &settings, uint32_t seed, uint32_t buildingId) {
    const SettingValue *value = settings.find("RoofType");
    if (!value) return thesisRoofType(footprint);
    std::string text = value->text;
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream words(text);
    std::vector<RoofType> types;
    for (std::string word; words >> word;) {
        std::optional<RoofType> type = roofTypeFromName(word);
        if (!type) throw InputError(value->loc, fmt::format("RoofType '{}' is none of {}", word, roofTypeNames()));
        types.push_back(*type);
    }
    if (types.empty()) throw InputError(value->loc, "RoofType names no roof type");
    return types[hashValues({seed, buildingId, streamTag(RandomStream::RoofChoice)}) % types.size()];
}

// How far the slopes reach in before they meet (see roofOptionsFor).
float halfDepth(const Footprint &footprint) {
    if (footprint.edgeCount() == 4 && isRightAngled(footprint))
        return std::min(footprint.edgeLength(0), footprint.edgeLength(1)) / 2;
    return 2 * signedArea(footprint.points) / footprint.perimeterBefore(footprint.edgeCount());
}

float lengthSetting(const SettingsStack &settings, const char *name, float otherwise) {
    std::optional<float> value = settings.number(name);
    if (!value) return otherwise;
    if (!(*value >= 0) || !std::isfinite(*value))
        throw InputError(settings.find(name)->loc, fmt::format("{} must be zero or more metres, not {}", name, *value));
    return *value;
}

std::optional<float> pitchSetting(const SettingsStack &settings) {
    std::optional<float> pitch = settings.number("RoofPitch");
    if (pitch && !(*pitch > 0 && *pitch < 90))
        throw InputError(settings.find("RoofPitch")->loc,
                         fmt::format("RoofPitch must be between 0° and 90°, not {}°", *pitch));
    return pitch;
}

}  // namespace

RoofType thesisRoofType(const Footprint &footprint) {
    bool gable = footprint.edgeCount() == 4 &&
        std::count(footprint.streetEdges.begin(), footprint.streetEdges.end(), true) == 1 && isRightAngled(footprint);
    return gable ? RoofType::Gable : RoofType::Mansard;
}

RoofOptions roofOptionsFor(const Footprint &footprint, const SettingsStack &settings, const BuildingHeights &heights,
                           uint32_t seed, uint32_t buildingId) {
    RoofOptions options;
    RoofType chosen = chosenType(footprint, settings, seed, buildingId);  // checked on flat buildings too
    options.type = heights.roof > 0 ? chosen : RoofType::Flat;
    options.overhang = lengthSetting(settings, "RoofOverhang", 0);
    options.parapetHeight = lengthSetting(settings, "ParapetHeight", kDefaultParapetHeight);
    if (std::optional<float> pitch = pitchSetting(settings)) {
        options.pitchDegrees = *pitch;
    } else if (heights.roof > 0) {
        float reach = options.type == RoofType::Mansard ? kMansardInset : halfDepth(footprint);
        // A sliver of a footprint would round to 90°, which no sloped roof can take.
        options.pitchDegrees = std::min(degrees(std::atan2(heights.roof, reach)), kSteepestDerivedPitch);
    }
    return options;
}

}  // namespace veduta
