// A building planned down to its rooms (digest-003 §1 and §2.2, L802–829, L1946–1950): on a
// lot, the sidewalk and the footprint; the footprint subdivided into apartments round a house
// corridor from the entrance; each apartment into rooms round its own corridor from its door.
// The ground floor's plan is every storey's (the thesis copies it upward), the stairwell's too.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "slg/building_placement.h"
#include "slg/corridors.h"
#include "slg/plan_extension.h"
#include "slg/plan_parameters.h"

namespace veduta {

struct ApartmentPlan {
    PlanShape outline;             // after the house corridor took its strip
    std::vector<PlanShape> rooms;  // the apartment corridor is what they leave of it (corridorPieces)
    Vec2d door;                    // the landmark its corridor starts at
    // The building's stairwell (L2009–2020) when it is one of these rooms: an index into them.
    // One apartment of a storey at most holds it, the same room on every storey.
    std::optional<size_t> stairwell;
};

struct StoreyPlan {
    std::vector<ApartmentPlan> apartments;  // the house corridor is what they leave (corridorPieces)
    Vec2d entrance;                         // the landmark of the house door
};

// What a plan lost on the way, for the warnings and the tests: each count is of faces the
// thesis's steps could not make (L1313) or corridors that did not reach.
struct PlanLosses {
    int deletedFaces = 0;       // landmark pairs no path made a face of
    int truncatedSearches = 0;  // path searches stopped at their limits
    int unreached = 0;          // apartments the house corridor does not reach
    int tooSmall = 0;           // faces whose side could not give up the corridor width
    PlanLosses &operator+=(const PlanLosses &o);
};

struct BuildingPlan {
    std::vector<Polygon2d> sidewalk;  // one quad per front edge of the lot
    Placement placement;              // the footprint on the lot
    StoreyPlan storey;                // the plan of every storey
    int storeys = 1;
    PlanLosses losses;
};

struct BuildingPlanParameters {
    double sidewalkWidth = 2.75;  // Table 11: 2.5–3 m
    PlacementParameters placement;
    PlanParameters storey;     // Table 13
    PlanParameters apartment;  // Table 16
    double houseCorridorWidth = 1.5, apartmentCorridorWidth = 1.5;
    double doorWidth = 1.0;       // a door from a corridor into an apartment or a room must fit
    StairwellRule stairwell;      // in a building of kStairwellMinimumStoreys or more
    bool entranceAtRear = false;  // eq 58: a shop or restaurant on the ground floor has the street
    int storeys = 1;
    SearchLimits limits;
};

// How far down planBuilding goes: a building drawn as a box needs its footprint only, one drawn
// storey by storey the house door too, one with its interiors every room.
enum class PlanDepth : uint8_t { Footprint, Entrance, Rooms };

// The plan of the building on a lot (a face of its block, with its sides) for the seed and the
// building's identity; none when the lot has no room for a sidewalk and a footprint. Every
// draw hashes the seed, the identity, the level and the face's index, so a plan is the same
// whatever was planned before it and a shallower plan is the deeper one's beginning.
std::optional<BuildingPlan> planBuilding(const PlanShape &lot, const FaceSides &sides,
                                         const BuildingPlanParameters &parameters, uint32_t seed, uint32_t identity,
                                         PlanDepth depth = PlanDepth::Rooms);

// The plan of a building whose footprint is given (an ATKIS or ALK outline, digest-003 §8.3):
// its storeys, apartments and rooms as on a lot, without sidewalk or placement; the
// footprint's edges keep their locations (a Street edge gets windows and may get the door).
BuildingPlan planInFootprint(const PlanShape &footprint, const FaceSides &sides,
                             const BuildingPlanParameters &parameters, uint32_t seed, uint32_t identity,
                             PlanDepth depth = PlanDepth::Rooms);

}  // namespace veduta
