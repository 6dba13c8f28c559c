#include "test_scenes.h"
#include "app/scene_loading.h"
#include "input_error.h"
#include "test_paths.h"

#include <unistd.h>

#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace veduta::test {

RenderScene sceneFromXml(const std::string &xml) {
    return buildRenderScene(readSceneText(xml, "test.xml", test::testData()));
}

SceneDescription defaultSceneAt(int width, int height, uint32_t samples) {
    SceneDescription d = loadSceneDescription("");
    d.camera.width = width;
    d.camera.height = height;
    d.settings.samplesPerPixel = samples;
    return d;
}

std::string sceneErrorOf(const std::string &xml) {
    return test::inputErrorOf([&] { sceneFromXml(xml); });
}

ScratchFolder::ScratchFolder(const std::string &name) :
    path_(std::filesystem::path(testing::TempDir()) / fmt::format("veduta_{}_{}", name, getpid())) {
    std::filesystem::create_directories(path_);
}

ScratchFolder::~ScratchFolder() { std::filesystem::remove_all(path_); }

std::filesystem::path ScratchFolder::write(const std::string &name, const std::string &text) const {
    std::filesystem::path file = path_ / name;
    std::ofstream(file) << text;
    return file;
}

}  // namespace veduta::test
