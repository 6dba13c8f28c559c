// Where the command line gets its scenes: a file, or the built-in default scene.
#pragma once

#include <string>

#include "description/scene_description.h"
#include "scene/render_scene.h"

namespace veduta {

// The text of scenes/default.xml, compiled into the program.
extern const char *const kDefaultSceneXml;

// An empty path means the built-in default scene.
SceneDescription loadSceneDescription(const std::string &path);

// buildRenderScene, with its warnings printed to stderr ("veduta: warning: file:line:col: …").
RenderScene buildSceneWithWarnings(const SceneDescription &description);

// Prints warnings to stderr, the first 20 of them and then how many more there were.
void printWarnings(const std::vector<std::string> &warnings);

}  // namespace veduta
