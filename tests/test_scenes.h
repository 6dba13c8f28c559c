// Small scenes written inline for tests, read through the same parser users go through.
#pragma once

#include <string>

#include "assembly/build_scene.h"

namespace veduta::test {

// Parses `xml` (which must hold a whole <scene>) and builds its RenderScene.
RenderScene sceneFromXml(const std::string &xml);

}  // namespace veduta::test
