// The generator for what a scene file lists directly: shapes, mesh files, prototypes and
// instances. It turns a SceneDescription into a RenderScene; later generators (terrain,
// city, GIS) add to the same builder.
#pragma once

#include <string>
#include <vector>

#include "description/scene_description.h"
#include "scene/render_scene.h"

namespace veduta {

// The sun where the scene puts it: its direction as given, or from a date, time and place.
Sun placeSun(const SceneDescription &description);

// The command line's --seed: `seed` becomes the scene seed and replaces every seed the file
// gives its elements (<render>, <buildings>, <city>, <landscape>), so that it reaches every
// random choice.
void replaceEverySeed(SceneDescription &description, uint32_t seed);

// Throws InputError at the place in the scene file a problem comes from (an unknown material
// or prototype, a mesh file that cannot be read, a rule that cannot be derived). Warnings
// ("file:line:col: message") go to `warnings` when it is given.
RenderScene buildRenderScene(const SceneDescription &description, std::vector<std::string> *warnings = nullptr);

}  // namespace veduta
