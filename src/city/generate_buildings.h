// The city generator for a scene's <buildings>: reads the rule file, then derives every
// building of the group into the render scene.
#pragma once

#include <string>
#include <vector>

#include "scene/render_scene.h"
#include "scene/scene_description.h"

namespace veduta {

// Warnings (a rule's probabilities renormalised, a clockwise footprint turned round, sizes that
// overflow a split) are appended as "file:line:col: message"; errors throw InputError.
void generateBuildings(const BuildingGroupDesc &group, RenderSceneBuilder &builder, std::vector<std::string> &warnings);

}  // namespace veduta
