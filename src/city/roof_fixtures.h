// Dormers and chimneys set on a built roof (roof_shapes.h): shed dormers (Schleppgauben) on the
// slopes that face a street, each a front with a window, two cheeks and a flatter roof that
// runs back into the slope; chimneys as stacks through the roof beside its ridge. They are
// placed by the building's seed and id, and only where they fit on their slope. docs/roofs.md.
#pragma once

#include <cstdint>

#include "city/building_settings.h"
#include "city/footprint.h"
#include "scene/mesh.h"

namespace veduta {

struct RoofFixtureOptions {
    int dormers = 0;             // per street-facing slope; 0: none
    float dormerWidth = 1.4f;    // metres
    float dormerHeight = 1.3f;   // the front's height above the slope
    float dormerPitch = 12;      // the dormer roof's pitch, degrees
    int chimneys = 0;            // per building
    float chimneyWidth = 0.5f;   // metres, square
    float chimneyHeight = 0.9f;  // above the highest roof point under it
};

// From the settings Dormers, DormerWidth, DormerHeight, Chimneys, ChimneyHeight (docs/buildings.md);
// InputError at a setting out of range.
RoofFixtureOptions roofFixtureOptionsFor(const SettingsStack &settings);

// The fixtures' triangles carry these values; the caller maps them to materials.
enum FixtureSurface : MaterialId { FixtureWall = 0, FixtureWindow = 1, FixtureRoof = 2 };

// The dormers and chimneys of `roof` (buildRoof's mesh, its covering marked RoofCovering), in
// the same world coordinates; empty when the options ask for none or none fits. A dormer
// needs a slope of 25° to 65° facing a street edge (within 20°), and the whole dormer on that
// slope; a slope takes as many as fit of the number asked, evenly spaced along its eaves.
Mesh roofFixtures(const Mesh &roof, const Footprint &footprint, const RoofFixtureOptions &options, uint32_t seed,
                  uint32_t buildingId);

}  // namespace veduta
