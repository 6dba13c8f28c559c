#include "slg/lot_building.h"

namespace veduta {

std::optional<LotBuilding> lotBuilding(const UrbanGeography &geography, const LotGeography &lot, uint32_t seed,
                                       uint32_t identity) {
    LotBuilding building;
    building.use = dominantUse(lot.weights);
    if (building.use == DominantUse::Unbebaut) return std::nullopt;
    PlanRandom random = parameterRandom(seed, identity);
    BuildingPlanParameters &p = building.parameters;
    p.storey = planParameters(geography, PlanLevel::Building);
    p.apartment = planParameters(geography, PlanLevel::Apartment);
    p.houseCorridorWidth = p.storey.gapWidth;
    p.apartmentCorridorWidth = p.apartment.gapWidth;
    p.stairwell.minimumArea = geography.stairwellArea;
    p.sidewalkWidth = sidewalkWidth(geography, random);

    PlacementParameters &placement = p.placement;
    placement.bauweise = bauweise(building.use, lot.locality);
    placement.alignment = alignment(placement.bauweise, random);
    building.orientation = roofOrientation(placement.bauweise, random);
    placement.sideRatio = sideRatio(geography, building.orientation, random);
    placement.buildingArea = averageBuildingArea(geography, building.use, lot.locality);
    // The footprint's sides are the storey plan's outline: none shorter than its faces may be.
    placement.minimumSide = lengthLimits(p.storey).minimum;

    p.storeys = storeyCount(geography, lot.city, building.use, lot.locality, random);
    building.storeyUses = stackStoreys(storeysPerUse(geography, p.storeys, lot.weights));
    p.entranceAtRear = !building.storeyUses.empty() && entranceSide(building.storeyUses.front()) == EntranceSide::Rear;
    return building;
}

}  // namespace veduta
