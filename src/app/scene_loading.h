// Where the command line gets its scenes: a file, or the built-in default scene.
#pragma once

#include <string>

#include "scene/scene_description.h"

namespace veduta {

// The text of scenes/default.xml, compiled into the program.
extern const char *const kDefaultSceneXml;

// An empty path means the built-in default scene.
SceneDescription loadSceneDescription(const std::string &path);

}  // namespace veduta
