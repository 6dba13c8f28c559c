// The procedural twin of a CityGML building (issue 18, docs/compare.md): what a <buildings>
// group needs to derive a building like it with a facade grammar — a footprint, the wall and
// roof heights, the roof type and the storeys.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "city/citygml_file.h"
#include "city/roof_shapes.h"
#include "core/vecmath.h"
#include "geodesy/map_projection.h"

namespace veduta {

struct TwinBuilding {
    std::string gmlId;
    uint32_t id = 0;               // cityGmlBuildingId(gmlId): the manual model's building id
    std::vector<Vec2f> footprint;  // metres east and north of the scene origin, counter-clockwise, simple
    double base = 0;               // the ground height it stands on
    double wallHeight = 0;         // eaves − base
    double roofHeight = 0;         // ridge − eaves
    std::optional<RoofType> roof;  // unset: the rules' own choice
    unsigned storeys = 1;
    double floorHeight = 0;  // wallHeight / storeys
};

// The twin of one building, or nothing (with a warning saying why) when it has no footprint
// to stand on: its footprint is the union of its ground surfaces (of its roofs' outlines seen
// from above when it has none); where that union is several pieces, the largest, and where
// it has courtyards, their outer outline, each with a warning. Points closer than 5 cm and
// ones within 2 cm of the line through their neighbours are dropped. Storeys come from
// storeysAboveGround, else from the wall height at 3.3 m a storey.
std::optional<TwinBuilding> deriveTwin(const CityGmlBuilding &building, const MapProjection &projection,
                                       std::vector<std::string> &warnings);

}  // namespace veduta
