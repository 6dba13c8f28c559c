// The city generator for a scene's <buildings>: reads the rule file, then derives every
// building of the group into the render scene.
#pragma once

#include <string>
#include <vector>

#include "city/masonry_maps.h"
#include "description/scene_description.h"
#include "geo/ground_height.h"
#include "scene/camera.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// Warnings (a rule's probabilities renormalised, a clockwise footprint turned round, sizes that
// overflow a split) are appended as "file:line:col: message"; errors throw InputError.
// A building placed on the ground gets a plinth (city/plinth.h) in the material "plinth".
// `seed` is the group's resolved seed (buildRenderScene).
// The rule file's <Masonry> walls are baked for `camera` into maps registered through
// `masonryMaps`; without them, those walls keep their model's texture (a warning says so).
void generateBuildings(const BuildingGroupDesc &group, uint32_t seed, const GroundHeight &ground,
                       RenderSceneBuilder &builder, std::vector<std::string> &warnings, const Camera *camera = nullptr,
                       const MasonryOutput &masonryMaps = {});

}  // namespace veduta
