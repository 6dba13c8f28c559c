// The landscape generator for a scene's <landscape> (docs/landscape.md): reads the DGM tiles
// and ATKIS layers, drapes the areas on the terrain and the roads, paths and rails over it,
// plants trees, and says where buildings stand.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "city/generate_buildings.h"
#include "scene/georeference.h"
#include "scene/render_scene.h"
#include "scene/scene_description.h"

namespace veduta {

// Emits the terrain (one mesh, a material per land class), the ribbons and the trees (an
// instance of a prototype each) into `builder`, in the local frame of the georeference's
// origin. Returns the ground for buildings: the lowest point of the finished terrain under a
// footprint. `seed` is the landscape's resolved seed (buildRenderScene). Throws InputError (a
// landscape without georeference, a DGM in another CRS, bad data).
GroundHeight generateLandscape(const LandscapeDesc &landscape, uint32_t seed,
                               const std::optional<Georeference> &georeference, RenderSceneBuilder &builder,
                               std::vector<std::string> &warnings);

}  // namespace veduta
