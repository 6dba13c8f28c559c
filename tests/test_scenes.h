// Small scenes written inline for tests, read through the same parser users go through.
#pragma once

#include <filesystem>
#include <string>

#include "assembly/build_scene.h"

namespace veduta::test {

// Parses `xml` (which must hold a whole <scene>) and builds its RenderScene.
RenderScene sceneFromXml(const std::string &xml);

// The built-in default scene's description at `width` × `height` pixels and `samples` per pixel.
SceneDescription defaultSceneAt(int width, int height, uint32_t samples);

// The message of the InputError that reading and building `xml` throws, or "no error".
std::string sceneErrorOf(const std::string &xml);

// A folder of its own under the test's temporary directory, removed with it.
class ScratchFolder {
  public:
    explicit ScratchFolder(const std::string &name);
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder &) = delete;
    ScratchFolder &operator=(const ScratchFolder &) = delete;

    const std::filesystem::path &path() const { return path_; }
    // Writes `text` to the file `name` in the folder and returns its path.
    std::filesystem::path write(const std::string &name, const std::string &text) const;

  private:
    std::filesystem::path path_;
};

}  // namespace veduta::test
