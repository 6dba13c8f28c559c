// Where a building stands on its lot (digest-003 §2.2 step 4 and §4.4, thesis L1393–1425 and
// L2826–2941): the band along the lot's front as deep as its shorter side, and in it the
// footprint, on the side boundaries or clear of them after the Bauweise, to the front, the
// middle or the back after the alignment.
#pragma once

#include <optional>

#include "slg/front_strip.h"
#include "slg/plan_random.h"

namespace veduta {

enum class Bauweise : uint8_t {
    Closed,    // geschlossen: wall to wall with both neighbours
    SemiOpen,  // the thesis's halboffen: on one side boundary, clear of the other
    Open,      // offen: clear of both
};

enum class Alignment : uint8_t { Front, Middle, Back };

struct PlacementParameters {
    Bauweise bauweise = Bauweise::Closed;
    Alignment alignment = Alignment::Front;
    double buildingArea = 100;  // the footprint aimed at (eq 46)
    double sideRatio = 1;       // depth over width (eq 51): above 1 gable to the street
    double minimumSide = 3;     // no side of the footprint shorter
    double sideDistance = 3;    // from a side boundary the building keeps clear of
};

struct Placement {
    PlanShape footprint;  // its front is edges 0 … sides.bottom.size() − 1
    FaceSides sides;
    Bauweise bauweise = Bauweise::Closed;  // as built: an open lot too narrow falls back
    double bandDepth = 0;                  // d of eq 56 after the rectification
};

// The footprint on a lot (behind its sidewalk) with the given sides; none when the lot has no
// room for a footprint of minimumSide. Its edges face the street where it stands on the front,
// the neighbour (NeighbourArea) where it stands on such a side boundary, a gap elsewhere.
std::optional<Placement> placeBuilding(const PlanShape &lot, const FaceSides &sides,
                                       const PlacementParameters &parameters, const PlanRandom &random);

}  // namespace veduta
