// The console models that cornices set (facade/cornice_run.h): one prototype per model file and
// material, shared by every building that sets it, read when first asked for.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>

#include "facade/cornice_run.h"
#include "scene/render_scene.h"

namespace veduta {

class ConsolePrototypes {
  public:
    explicit ConsolePrototypes(RenderSceneBuilder &builder) : builder_(builder) {}

    // The prototype of `file` (the console set's model, found where its cornice file lies) in the
    // set's material. Throws InputError at the set's console when the file cannot be read.
    PrototypeId get(const std::filesystem::path &file, const ConsoleSet &set);

  private:
    RenderSceneBuilder &builder_;
    std::map<std::pair<std::string, MaterialId>, PrototypeId> prototypes_;
};

}  // namespace veduta
