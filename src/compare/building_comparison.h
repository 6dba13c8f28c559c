// The buildings of two scenes of one place, paired and compared (docs/compare.md): by building
// id where both have it, else by the most overlap seen from above; per pair the footprint IoU,
// the eaves, ridge and volume errors and whether the roof types agree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/height_map.h"
#include "scene/render_scene.h"

namespace veduta {

// One building of one scene, measured on its height map and from its generator's record.
struct MeasuredBuilding {
    uint32_t id = 0;
    double footprintArea = 0;  // m², of its cells (BuildingComparison::groundPlans says which)
    double volume = 0;         // m³, over those cells: under the topmost surface, over its base (2.5D)
    std::optional<BuildingRecord> record;
    double centreX = 0, centreY = 0;  // of its cells
};

struct BuildingPair {
    std::optional<MeasuredBuilding> a, b;  // one is unset for a building the other scene lacks
    std::string matchedBy;                 // "id", "overlap" or "none"
    double footprintIou = 0;
    std::optional<double> eavesError, ridgeError;  // b − a, metres, where both have records
    std::optional<double> volumeError;             // (b − a) / a
    std::optional<bool> roofAgrees;                // where both know their roof type
};

struct BuildingComparison {
    // Whether footprints are the recorded ground plans of both scenes (HeightMap::plan); else
    // a building's cells are those it tops, roof overhangs included.
    bool groundPlans = false;
    std::vector<BuildingPair> pairs;  // a's buildings in id order, then b's that no a matched
    size_t matchedById = 0, matchedByOverlap = 0, onlyA = 0, onlyB = 0;
    double meanFootprintIou = 0;                                                  // over matched pairs
    double meanAbsEavesError = 0, meanAbsRidgeError = 0, meanAbsVolumeError = 0;  // over pairs that have them
    double roofAgreement = 0;  // the share of pairs with both roof types that agree
};

// Both height maps must be of the same grid.
BuildingComparison compareBuildings(const RenderScene &a, const HeightMap &mapA, const RenderScene &b,
                                    const HeightMap &mapB);

}  // namespace veduta
