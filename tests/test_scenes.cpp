#include "test_scenes.h"

#include <unistd.h>

#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace veduta::test {

RenderScene sceneFromXml(const std::string &xml) {
    return buildRenderScene(readSceneText(xml, "test.xml", VEDUTA_TEST_DATA));
}

std::string sceneErrorOf(const std::string &xml) {
    try {
        sceneFromXml(xml);
    } catch (const InputError &e) {
        return e.what();
    }
    return "no error";
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
