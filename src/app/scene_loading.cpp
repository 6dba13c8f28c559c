#include "app/scene_loading.h"

#include <cstdio>
#include <filesystem>

#include "assembly/build_scene.h"

namespace veduta {

SceneDescription loadSceneDescription(const std::string &path) {
    if (path.empty())
        return readSceneText(kDefaultSceneXml, "<built-in default scene>", std::filesystem::current_path());
    return readSceneFile(path);
}

RenderScene buildSceneWithWarnings(const SceneDescription &description) {
    std::vector<std::string> warnings;
    try {
        RenderScene scene = buildRenderScene(description, &warnings);
        printWarnings(warnings);
        return scene;
    } catch (...) {
        printWarnings(warnings);  // they may say why
        throw;
    }
}

void printWarnings(const std::vector<std::string> &warnings) {
    constexpr size_t kShown = 20;
    for (size_t i = 0; i < warnings.size() && i < kShown; ++i)
        std::fprintf(stderr, "veduta: warning: %s\n", warnings[i].c_str());
    if (warnings.size() > kShown) std::fprintf(stderr, "veduta: warning: … and %zu more\n", warnings.size() - kShown);
}

}  // namespace veduta
