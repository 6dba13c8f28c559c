// The city generator for a scene's <city>: a CityData file (docs/citydata.md) whose blocks
// without lots are cut into perimeter lots (docs/lots.md) and whose lots are built with the
// grammar of its rule files (docs/buildings.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/render_scene.h"
#include "scene/scene_description.h"

namespace veduta {

// Builds every lot of the city; its buildings take the ids from `firstBuildingId` on, in the
// order of the file's blocks and lots. Returns how many ids it took. Warnings (a clockwise
// block, probabilities renormalised …) are appended once each as "file:line:col: message";
// errors throw InputError.
uint32_t generateCity(const CityDesc &city, uint32_t firstBuildingId, RenderSceneBuilder &builder,
                      std::vector<std::string> &warnings);

}  // namespace veduta
