#include "app/scene_loading.h"

#include <filesystem>

namespace veduta {

SceneDescription loadSceneDescription(const std::string &path) {
    if (path.empty()) return readSceneText(kDefaultSceneXml, "<built-in default scene>", std::filesystem::current_path());
    return readSceneFile(path);
}

}  // namespace veduta
