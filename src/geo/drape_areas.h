// Draping ATKIS areas on the DGM (Rilling 2006, §4.5, issue 8): one terrain mesh over the whole
// grid with the area outlines cut in, each triangle inside one grid triangle and one area (or
// none), so the surface is the grid's own piecewise-linear surface and the caller can give
// every area its material. docs/draping.md describes the choices.
#pragma once

#include <cstdint>
#include <vector>

#include "geo/atkis.h"
#include "geo/height_grid.h"
#include "geodesy/local_frame.h"
#include "scene/mesh.h"

namespace veduta {

struct DrapeArea {
    MapRing outline;  // a simple polygon of the grid's CRS, either winding; self-crossings count even–odd
    LandClass landClass = LandClass::Other;
    uint32_t objectIndex = 0;  // the caller's object, for materials
    std::string name;          // the object for messages ("file.gpkg: layer x, feature 7"); empty: its index
};

struct DrapeOptions {
    double textureTile = 10.0;  // metres per texture repeat: uv = local xy / textureTile
};

inline constexpr uint32_t kNoArea = ~0u;

struct DrapedTerrain {
    // Local coordinates (LocalFrame), up-facing (counter-clockwise seen from above), welded:
    // vertices shared between pieces are one vertex. Normals area-weighted; uvs local xy /
    // textureTile. triangleMaterials are 0 until the caller assigns them from triangleArea.
    Mesh mesh;
    std::vector<uint32_t> triangleArea;  // per triangle: index into the areas, or kNoArea (bare terrain)
    std::vector<float> waterLevel;       // per area: the level of a Water area, NaN for other classes
};

// Where areas overlap (ATKIS allows it, Rilling 2006, §3.2), the area of the higher priority wins;
// between equal priorities, the earlier area. A city's streets (CityStreet) 10 > Water and
// River 9 > Road, Path, Rail 8 > Settlement 7 > Park 6 > Forest 5 > Shrubs, TreeRow, Hedge 4 >
// Farmland 3 > Grassland 2 > Other 1.
int drapePriority(LandClass landClass);

// The grid's terrain with the areas cut in. Cells with a NaN corner are left out; outline
// parts outside the grid are ignored. Every vertex of a Water area (inside or on its outline)
// is then set to its level, the minimum terrain height along its outline (waterLevel); a
// vertex of two water areas takes the lower. Throws InputError for an outline with a
// non-finite coordinate or fewer than 3 distinct points.
DrapedTerrain drapeAreas(const HeightGrid &grid, const LocalFrame &frame, const std::vector<DrapeArea> &areas,
                         const DrapeOptions &options);

}  // namespace veduta
