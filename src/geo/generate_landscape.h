// The landscape generator for a scene's <landscape> (docs/landscape.md): reads the DGM tiles
// and ATKIS layers, drapes the areas on the terrain and the roads, paths and rails over it,
// plants trees, and says where buildings stand.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "description/scene_description.h"
#include "geo/atkis.h"
#include "geo/ground_height.h"
#include "geo/height_grid.h"
#include "geo/terrain_surface.h"
#include "geodesy/georeference.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// What the landscape leaves for the generators after it: the finished terrain (for a city's
// streets) and the ground for buildings, the lowest point of that terrain under a footprint.
struct LandscapeGround {
    std::shared_ptr<const TerrainSurface> surface;
    GroundHeight ground;
};

// A plain polygon in the local frame (x east, y north, metres from the origin), either winding.
using LocalPolygon = std::vector<Vec2d>;

// What a <landscape>'s files hold, read: the DGM (tiles mosaicked) and the objects of its ATKIS
// layers, in the scene's CRS. Read before the cities, whose streets may grow on it.
struct LandscapeData {
    HeightGrid grid;
    std::vector<AtkisObject> objects;
};

// Reads the landscape's DGM and layers, with a warning for each layer's objects the landscape
// does not draw. Throws InputError (a landscape without georeference, a DGM in another CRS,
// bad data).
LandscapeData readLandscape(const LandscapeDesc &landscape, const std::optional<Georeference> &georeference,
                            std::vector<std::string> &warnings);

// Emits the terrain (one mesh, a material per land class), the ribbons and their markings and
// the trees (an instance of a prototype each) into `builder`, in the local frame of the
// georeference's origin. Through `addProcedural` the land and pavement materials get their
// procedural textures (geo/land_materials.h); without it they are plain colours. With a
// `camera`, railways near it get their sleepers and rails as geometry (geo/track_geometry.h). `streetAreas`, the pieces
// of the cities' streets and sidewalks (their union is the street surface), are cut into the terrain as CityStreet
// areas above every ATKIS area, and trees keep off them as off ribbons. `seed` is the landscape's resolved seed
// (buildRenderScene). Throws InputError (a landscape without georeference, a DGM in another CRS, bad data).
LandscapeGround generateLandscape(const LandscapeDesc &landscape, LandscapeData data, uint32_t seed,
                                  const std::optional<Georeference> &georeference,
                                  const std::vector<LocalPolygon> &streetAreas, RenderSceneBuilder &builder,
                                  std::vector<std::string> &warnings, const AddProcedural &addProcedural = {},
                                  const Camera *camera = nullptr);
// The same, reading the landscape's files first (readLandscape).
LandscapeGround generateLandscape(const LandscapeDesc &landscape, uint32_t seed,
                                  const std::optional<Georeference> &georeference,
                                  const std::vector<LocalPolygon> &streetAreas, RenderSceneBuilder &builder,
                                  std::vector<std::string> &warnings, const AddProcedural &addProcedural = {},
                                  const Camera *camera = nullptr);

}  // namespace veduta
