#include "preview/example_scenes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "assembly/build_scene.h"
#include "description/scene_description.h"
#include "test_paths.h"

namespace veduta::test {

namespace {

// Whether every file under ../shared the scene names is there.
bool hasItsSharedData(const std::filesystem::path &scene) {
    std::ifstream in(scene);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string marker = "\"../../shared/";
    for (size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + 1)) {
        size_t end = text.find('"', at + 1);
        if (!std::filesystem::exists(scene.parent_path() / text.substr(at + 1, end - at - 1))) return false;
    }
    return true;
}

}  // namespace

std::vector<std::filesystem::path> exampleScenes() {
    std::vector<std::filesystem::path> files;
    for (const auto &entry : std::filesystem::recursive_directory_iterator(sourceFile("scenes"))) {
        if (entry.path().extension() == ".xml" && hasItsSharedData(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

RenderScene exampleScene(const std::filesystem::path &file, int width) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    SceneDescription description = readSceneText(text.str(), file.string(), file.parent_path());
    if (width > 0) {
        Camera &camera = description.camera;
        camera.height = std::max(1, int(std::lround(double(width) * camera.height / camera.width)));
        camera.width = width;
    }
    return buildRenderScene(description);
}

}  // namespace veduta::test
