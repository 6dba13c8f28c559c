#include "city/lot_subdivision.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "city/building_settings.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

struct SettingField {
    const char *name;
    float LotSettings::*member;
};

constexpr SettingField kSettingFields[] = {
    {"MinBuildingLength", &LotSettings::minBuildingLength},
    {"MaxBuildingLength", &LotSettings::maxBuildingLength},
    {"MinBuildingDepth", &LotSettings::minBuildingDepth},
    {"MinBuildingInnerLength", &LotSettings::minBuildingInnerLength},
    {"MaxLotArea", &LotSettings::maxLotArea},
    {"MinLotArea", &LotSettings::minLotArea},
    {"MinLotAngle", &LotSettings::minLotAngleDegrees},
    {"HousingDensity", &LotSettings::housingDensity},
    {"RoadMargin", &LotSettings::roadMargin},
    {"BuildingMargin", &LotSettings::buildingMargin},
};

// A setting out of range: `setting` is the one to blame; a range between two settings names
// the second as `other`, blamed when `setting` was left at its default.
struct SettingProblem {
    const char *setting;
    const char *other;
    std::string message;
};

std::optional<SettingProblem> findProblem(const LotSettings &s) {
    auto problem = [](const char *setting, float value, const char *range) {
        return SettingProblem{setting, nullptr, fmt::format("{} must be {}, not {}", setting, range, value)};
    };
    if (!(s.minBuildingLength > 0)) return problem("MinBuildingLength", s.minBuildingLength, "positive");
    if (!(s.maxBuildingLength >= s.minBuildingLength)) {
        return SettingProblem{"MaxBuildingLength", "MinBuildingLength",
                              fmt::format("MaxBuildingLength ({}) must not be below MinBuildingLength ({})",
                                          s.maxBuildingLength, s.minBuildingLength)};
    }
    if (!(s.minBuildingDepth > 0)) return problem("MinBuildingDepth", s.minBuildingDepth, "positive");
    if (!(s.minBuildingInnerLength >= 0)) {
        return problem("MinBuildingInnerLength", s.minBuildingInnerLength, "zero or more");
    }
    if (!(s.maxLotArea > 0)) return problem("MaxLotArea", s.maxLotArea, "positive");
    if (!(s.minLotArea >= 0)) return problem("MinLotArea", s.minLotArea, "zero or more");
    if (!(s.minLotAngleDegrees >= 0 && s.minLotAngleDegrees < 180)) {
        return problem("MinLotAngle", s.minLotAngleDegrees, "in [0, 180)");
    }
    if (!(s.housingDensity >= 0 && s.housingDensity <= 1)) {
        return problem("HousingDensity", s.housingDensity, "in [0, 1]");
    }
    // An infinite margin would be an infinite offset, which CGAL cannot construct.
    if (!(std::isfinite(s.roadMargin) && s.roadMargin >= 0)) {
        return problem("RoadMargin", s.roadMargin, "finite and zero or more");
    }
    if (!(std::isfinite(s.buildingMargin) && s.buildingMargin >= 0)) {
        return problem("BuildingMargin", s.buildingMargin, "finite and zero or more");
    }
    return std::nullopt;
}

// Interior angle at point i of a counter-clockwise polygon, in degrees (above 180 at reflex
// corners).
float interiorAngleDegrees(const std::vector<Vec2f> &polygon, size_t i) {
    size_t n = polygon.size();
    Vec2f prev = polygon[(i + n - 1) % n], here = polygon[i], next = polygon[(i + 1) % n];
    float ax = prev.x - here.x, ay = prev.y - here.y, bx = next.x - here.x, by = next.y - here.y;
    // Turning counter-clockwise from the outgoing to the incoming edge sweeps the interior.
    float angle = std::atan2(bx * ay - by * ax, bx * ax + by * ay);
    if (angle < 0) angle += 2 * kPi;
    return angle * (180 / kPi);
}

bool hasAllowedAngles(const std::vector<Vec2f> &polygon, float minDegrees) {
    for (size_t i = 0; i < polygon.size(); ++i) {
        if (!(interiorAngleDegrees(polygon, i) > minDegrees)) return false;
    }
    return true;
}

struct AlgorithmName {
    const char *name;
    LotSubdivision algorithm;
};

constexpr AlgorithmName kAlgorithmNames[] = {
    {"perimeter", LotSubdivision::Perimeter}, {"recursive", LotSubdivision::Recursive}, {"obb", LotSubdivision::Obb},
    {"skeleton", LotSubdivision::Skeleton},   {"schrader", LotSubdivision::Schrader},
};

LotSubdivision algorithmFrom(const SettingValue &value) {
    for (const AlgorithmName &entry : kAlgorithmNames) {
        if (value.text == entry.name) return entry.algorithm;
    }
    throw InputError(
        value.loc,
        fmt::format("LotSubdivision must be perimeter, recursive, obb, skeleton or schrader, not '{}'", value.text));
}

}  // namespace

void checkLotSettings(const LotSettings &settings, const std::optional<FileLoc> &loc) {
    if (std::optional<SettingProblem> problem = findProblem(settings)) lots::fail(loc, problem->message);
}

LotSettings lotSettingsFrom(const SettingsStack &stack) {
    LotSettings settings;
    if (const SettingValue *algorithm = stack.find("LotSubdivision")) settings.algorithm = algorithmFrom(*algorithm);
    for (const SettingField &field : kSettingFields) {
        if (std::optional<float> value = stack.number(field.name)) settings.*field.member = *value;
    }
    std::optional<SettingProblem> problem = findProblem(settings);
    if (!problem) return settings;
    const SettingValue *blamed = stack.find(problem->setting);
    if (!blamed && problem->other) blamed = stack.find(problem->other);
    throw InputError(blamed ? blamed->loc : FileLoc{}, problem->message);
}

std::vector<Footprint> subdivideBlock(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                      const std::optional<FileLoc> &loc) {
    switch (settings.algorithm) {
    case LotSubdivision::Recursive: return recursiveLots(block, settings, seed, blockId, loc);
    case LotSubdivision::Obb: return obbLots(block, settings, seed, blockId, loc);
    case LotSubdivision::Skeleton: return skeletonLots(block, settings, seed, blockId, loc);
    case LotSubdivision::Schrader: return schraderLots(block, settings, seed, blockId, loc);
    case LotSubdivision::Perimeter: break;
    }
    // The fallback is for blocks without room for a ring, not for rings the filters emptied.
    std::vector<Footprint> pieces = lots::perimeterPieces(block, settings, seed, blockId, loc);
    if (pieces.empty()) return recursiveLots(block, settings, seed, blockId, loc);
    return filterLots(std::move(pieces), settings, seed, blockId);
}

std::vector<Footprint> filterLots(std::vector<Footprint> lots, const LotSettings &settings, uint32_t seed,
                                  uint32_t blockId) {
    std::vector<Footprint> kept;
    for (size_t i = 0; i < lots.size(); ++i) {
        if (!(signedArea(lots[i].points) > settings.minLotArea)) continue;
        if (!hasAllowedAngles(lots[i].points, settings.minLotAngleDegrees)) continue;
        uint32_t key = hashValues({seed, blockId, uint32_t(i), streamTag(RandomStream::LotHousingDensity)});
        if (!(bitsToUnitFloat(key) < settings.housingDensity)) continue;
        kept.push_back(std::move(lots[i]));
    }
    return kept;
}

namespace lots {

void fail(const std::optional<FileLoc> &loc, const std::string &message) {
    if (loc) throw InputError(*loc, message);
    throw LotError(message);
}

void checkBlock(const Block &block, const std::optional<FileLoc> &loc) {
    if (block.points.size() < 3) fail(loc, fmt::format("a block needs at least 3 points, not {}", block.points.size()));
    if (block.streetEdges.size() != block.points.size()) {
        fail(loc,
             fmt::format("a block of {} edges has {} street flags", block.points.size(), block.streetEdges.size()));
    }
    for (Vec2f p : block.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(loc, "a block point is not a finite number");
    }
    if (!isSimplePolygon(block.points)) fail(loc, "the block's outline crosses or touches itself (or has no area)");
    if (!isCounterClockwise(block.points)) fail(loc, "the block runs clockwise; lots need it counter-clockwise");
}

float normalBetween(float lo, float hi, uint32_t key) {
    // Box–Muller from two independent uniform draws; 1 − u keeps the logarithm finite. The two
    // constants make the draws two of one key, as the sampler's make its pair's coordinates.
    float u1 = 1 - bitsToUnitFloat(mix32(key ^ 0x85ebca6bu));
    float u2 = bitsToUnitFloat(mix32(key ^ 0xc2b2ae35u));
    float gaussian = std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
    return std::clamp((lo + hi) / 2 + gaussian * (hi - lo) / 6, lo, hi);
}

bool checkedAndOnAStreet(const Block &block, const LotSettings &settings, const std::optional<FileLoc> &loc) {
    checkBlock(block, loc);
    checkLotSettings(settings, loc);
    return std::find(block.streetEdges.begin(), block.streetEdges.end(), true) != block.streetEdges.end();
}

}  // namespace lots

}  // namespace veduta
