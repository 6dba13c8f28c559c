#include "slg/edge_location.h"

#include <array>

namespace veduta {

namespace {

constexpr std::array<std::string_view, kEdgeLocationCount> kNames = {
    "street",
    "gap",
    "neighbour-area",
    "window-to-street",
    "window-to-gap",
    "main-entrance",
    "entrance",
    "house-corridor",
    "neighbour-apartment",
    "apartment-corridor",
    "neighbour-room",
    "inner-main-entrance",
    "inner-entrance",
    "inner-stair-entrance",
};

}  // namespace

std::string_view locationName(EdgeLocation location) { return kNames.at(size_t(location)); }

std::optional<EdgeLocation> locationNamed(std::string_view name) {
    for (size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return EdgeLocation(i);
    return std::nullopt;
}

bool isWindow(EdgeLocation location) {
    return location == EdgeLocation::WindowToStreet || location == EdgeLocation::WindowToGap;
}

bool isDoor(EdgeLocation location) {
    switch (location) {
    case EdgeLocation::MainEntrance:
    case EdgeLocation::Entrance:
    case EdgeLocation::InnerMainEntrance:
    case EdgeLocation::InnerEntrance:
    case EdgeLocation::InnerStairEntrance: return true;
    default: return false;
    }
}

bool isOuter(EdgeLocation location) { return location <= EdgeLocation::Entrance; }

}  // namespace veduta
