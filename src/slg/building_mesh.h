// A planned building as a mesh at a level of detail (digest-003 §3.2–3.5): the outer walls
// storey by storey with their windows and the house door, the roof once on top, and at the
// nearest level the interiors behind the glass — each room's and each corridor's floor and
// ceiling, the rooms' walls, and in a stairwell a flight of steps up from every storey but the
// top; at the coarsest, one quad per side of the building and the simple roof (14 triangles for
// a gable house on four corners, Table 17). One indexed mesh per level, its corners shared where
// the pieces meet (§3.2). Flat shading (the digest's suggestion for path tracing): no vertex
// normals. Texture coordinates (§3.3) count motifs of one storey's height square: a wall's
// texture is tiled along the walls and up the storeys, u running on round a storey from wall to
// wall (eq 35's tiled mapping) so that it crosses the corners without a seam but at the first;
// floors and roofs take the same squares across the plan; a door's or a pane's image is
// stretched over it once (the simple mapping). Each motif is a material of its own rather than
// a rectangle of one atlas image, so that glass stays glass.
#pragma once

#include <cstdint>
#include <optional>

#include "scene/mesh.h"
#include "slg/building_plan.h"
#include "slg/plan_extension.h"
#include "slg/urban_geography.h"

namespace veduta {

enum class BuildingLod : uint8_t {
    Rooms,    // LOD0: Storeys, and behind the glass the rooms, the corridors' floors and ceilings, the stairs
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

// The footprint edge that the segment a → b lies on, if any (the first where it lies on two).
std::optional<size_t> shellEdgeUnder(const PlanShape &shell, Vec2d a, Vec2d b);

// Where a room's (or a corridor's) floor ends: its outline moved in by the wall thickness along
// the shell and by half of it elsewhere, so that two spaces side by side leave one wall between
// them; for each of its edges, the footprint edge it runs inside of, where it does. None when
// the space is narrower than its walls.
struct SpaceFloor {
    Polygon2d points;  // counter-clockwise
    std::vector<std::optional<size_t>> shellEdges;
};
std::optional<SpaceFloor> insideWalls(const PlanShape &space, const PlanShape &shell, double wallThickness);

Mesh buildingMesh(const BuildingPlan &plan, const BuildingShape &shape, BuildingLod lod,
                  const BuildingMaterials &materials);

}  // namespace veduta
