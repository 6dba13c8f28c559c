// What the urban-geography cascade makes of a lot's building (digest-003 §4.4–4.5): the lot's
// land uses and locality decide the footprint's area, Bauweise, alignment and proportions, the
// sidewalk, the storeys and their uses, where the house door is, and the plan parameters of the
// storey and the apartments — everything planBuilding needs.
#pragma once

#include <optional>
#include <vector>

#include "slg/building_plan.h"
#include "slg/urban_geography.h"

namespace veduta {

struct LotGeography {
    LandUseWeights weights{};  // the lot's own (lotWeights of its block's)
    Locality locality = Locality::Mantel;
    std::optional<CitySize> city;  // none: a Mittelstadt (footnote 78)
};

struct LotBuilding {
    BuildingPlanParameters parameters;
    DominantUse use = DominantUse::Wohngebiet;
    std::vector<StoreyUse> storeyUses;                             // from the ground floor up (eq 62)
    RoofOrientation orientation = RoofOrientation::Traufstaendig;  // eq 50
};

// None for open land (Unbebaut: no building, eq 48). Every draw is the cascade's
// (parameterRandom) for the seed and the building's identity.
std::optional<LotBuilding> lotBuilding(const UrbanGeography &geography, const LotGeography &lot, uint32_t seed,
                                       uint32_t identity);

}  // namespace veduta
