// What lies beyond an edge of a plan (digest-003 §2.1, thesis L1102–1124): the fourteen
// "Lagen" that later decide which wall, window or door the edge becomes.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace veduta {

enum class EdgeLocation : uint8_t {
    // Outer locations, towards what surrounds a building.
    Street,
    Gap,            // Zwischenraum: a yard, a garden, the space between open buildings
    NeighbourArea,  // a neighbouring lot or building, wall to wall
    WindowToStreet,
    WindowToGap,
    MainEntrance,  // the house door
    Entrance,      // a shop's or restaurant's own street door
    // Inner locations, inside a building.
    HouseCorridor,
    NeighbourApartment,
    ApartmentCorridor,
    NeighbourRoom,
    InnerMainEntrance,  // an apartment's door to the house corridor
    InnerEntrance,      // a room's door
    InnerStairEntrance,
};

inline constexpr int kEdgeLocationCount = 14;

// The name in rule files and dumps: "street", "gap", "neighbour-area", "window-to-street", …
std::string_view locationName(EdgeLocation location);
std::optional<EdgeLocation> locationNamed(std::string_view name);

bool isWindow(EdgeLocation location);
bool isDoor(EdgeLocation location);
// A window or door in an outer wall, or a plain outer wall: what faces outside the building.
bool isOuter(EdgeLocation location);

}  // namespace veduta
