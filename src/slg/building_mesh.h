// A planned building as a mesh at a level of detail (digest-003 §3.2–3.5): the outer walls
// storey by storey with their windows and the house door, the roof once on top, and at the
// nearest level the apartments' rooms behind the glass; at the coarsest, one quad per side of
// the building and the simple roof (14 triangles for a gable house on four corners, Table 17).
// Flat shading (the digest's suggestion for path tracing): no vertex normals; texture
// coordinates in metres along the wall and up, or across the plan.
#pragma once

#include <cstdint>

#include "scene/mesh.h"
#include "slg/building_plan.h"
#include "slg/plan_extension.h"
#include "slg/urban_geography.h"

namespace veduta {

enum class BuildingLod : uint8_t {
    Rooms,    // LOD0: Storeys, and behind the glass each room's floor, ceiling and walls
    Storeys,  // LOD1: the outer walls storey by storey with windows and the house door, the roof
    Box,      // LOD2: one quad per side at the building's full height, the roof
};

struct BuildingMaterials {
    MaterialId wall = 0, glass = 0, door = 0, roof = 0, interior = 0;
};

struct BuildingShape {
    double base = 0;  // the ground under the footprint
    double storeyHeight = 3;
    RoofKind roof = RoofKind::Gable;
    RoofOrientation orientation = RoofOrientation::Traufstaendig;  // eaves (or gable) to the street
    double roofHeight = 3;                                         // eq 64
    WindowRule windows;                                            // on the street and gap walls
    double sill = 0.9, windowHeight = 1.5;
    double doorWidth = 1.2, doorHeight = 2.3;
    double wallThickness = 0.3;  // Table 12: rooms stand this far inside the shell, half that from each other
    double slab = 0.25;          // a room's ceiling below the next storey's floor
};

Mesh buildingMesh(const BuildingPlan &plan, const BuildingShape &shape, BuildingLod lod,
                  const BuildingMaterials &materials);

}  // namespace veduta
