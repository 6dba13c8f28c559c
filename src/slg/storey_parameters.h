// What a storey of Schrader's buildings is made of besides its plan (digest-003 §4.6, thesis
// §6.6.1): its height, how far its inner walls go, and its windows and doors, which the
// elevation (seed 003 §3.1) cuts into the plan's outer edges. Table 15's retail ground floor is
// the one set the thesis gives; rules/slg/urban-geography.xml holds them.
#pragma once

#include <cstdint>
#include <optional>

namespace veduta {

// A storey's one use (thesis §6.6), declared in the order eq 62 stacks them from the ground up:
// shops, restaurants or industry at the street, offices above, flats on top.
enum class StoreyUse : uint8_t { Einzelhandel, Gastronomie, Industrie, Buero, Wohnen };
inline constexpr int kStoreyUses = 5;

// Innenausbau: which inner walls the elevation builds (every room's, only the apartments', or
// only the lining of the outer walls, for a shop floor that is one room).
enum class FitOut : uint8_t { Rooms, Apartments, Storey };

// einfach getrennt | mehrfach getrennt | mehrfach zusammenhängend (thesis §5.2.3).
enum class WindowArrangement : uint8_t {
    Single,      // one window
    Separated,   // windows `spacing` apart
    Contiguous,  // a row of windows with no wall between them (a shop front)
};

enum class DoorAlignment : uint8_t { Left, Centre, Right };

// The thesis's window 9-tuple (footnote 80); no canopy depth means no canopy.
struct WindowParameters {
    double height = 0, sill = 0, width = 0;
    WindowArrangement placement = WindowArrangement::Single;
    double spacing = 0, wallDistance = 0;
    bool glass = true;
    std::optional<double> canopyDepth;
};

// The thesis's door 6-tuple (footnote 81).
struct DoorParameters {
    double height = 0, width = 0;
    DoorAlignment alignment = DoorAlignment::Centre;
    bool door = true;
    std::optional<double> canopyDepth;
};

// One predefined storey set: for a use, on the ground floor or above it (eq 62 step 3).
struct StoreyParameters {
    StoreyUse use = StoreyUse::Wohnen;
    bool groundFloor = true;
    double height = 0;
    FitOut fitOut = FitOut::Rooms;
    WindowParameters frontWindows, backWindows;
    DoorParameters buildingDoor, innerDoor, outerDoor;
};

}  // namespace veduta
