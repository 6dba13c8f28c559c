// Which roof a building gets from its settings (issue 7; docs/buildings.md, "Roof settings"):
// RoofType names one type, or several that buildings choose from by their id; RoofPitch,
// RoofOverhang and ParapetHeight shape it. Without RoofType a building keeps Bilke's choice
// (roofs.h: a gable over a rectangular house on one street, a mansard otherwise).
#pragma once

#include <cstdint>

#include "city/building_settings.h"
#include "city/footprint.h"
#include "city/roof_shapes.h"

namespace veduta {

inline constexpr float kDefaultParapetHeight = 0.8f;  // ParapetHeight, metres

// Bilke's choice (Bilke 2009, §2.4.3, CreateRoof), what a building gets without RoofType: a
// gable when the footprint has four vertices, exactly one street edge and right angles (within
// kRightAngleToleranceDegrees); a mansard otherwise.
RoofType thesisRoofType(const Footprint &footprint);

// The roof options for one building. RoofHeight 0 gives a flat roof. Without RoofPitch, the
// pitch is the one that raises the roof RoofHeight over the building's half depth (the half
// shorter side of a rectangle, else 2·area / perimeter, the radius of a circle of the same
// proportions), or over a mansard's slope width. Gables stand on every end of a ridge
// (roof_shapes.h). InputError at the setting for an unknown type, a pitch outside (0°, 90°)
// or a negative overhang or parapet.
RoofOptions roofOptionsFor(const Footprint &footprint, const SettingsStack &settings, const BuildingHeights &heights,
                           uint32_t seed, uint32_t buildingId);

}  // namespace veduta
