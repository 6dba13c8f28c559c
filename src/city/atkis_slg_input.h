// ATKIS and ALK data as the input of <slg level="atkis"> (digest-003 §8.3): the settlement areas
// (Objektart 2101 Ortslage, 2111–2114) become districts or blocks with the land use their
// Objektart names, ALK building footprints (Folie 011) buildings planned inside their outlines.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geo/atkis.h"
#include "geodesy/local_frame.h"
#include "slg/plan_geometry.h"
#include "slg/urban_geography.h"

namespace veduta {

struct SlgSettlement {
    Polygon2d outline;           // counter-clockwise, local metres
    std::optional<LandUse> use;  // none: mixed, the tables' defaults (2101, 2113)
};

struct SlgFootprint {
    Polygon2d outline;      // counter-clockwise, local metres
    uint32_t identity = 0;  // hashed from the object's id: the same building from the same data
};

struct SlgLandInput {
    std::vector<SlgSettlement> settlements;
    std::vector<SlgFootprint> footprints;
    int unusable = 0;  // outlines left out: fewer than three corners, or crossing themselves
};

// The settlement areas and building footprints among `objects`, in the local frame.
SlgLandInput slgLandInput(const std::vector<AtkisObject> &objects, const LocalFrame &frame);

}  // namespace veduta
