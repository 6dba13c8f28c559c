// Finkenzeller's buildings in a scene (<modular_building>, docs/facades.md): the structure and
// style files read, the building assembled (facade/facade_building.h), its masonry baked into
// maps at the texels the camera asks for (city/masonry_maps.h), its windows and consoles set as
// instances of their models.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "city/console_prototypes.h"
#include "city/masonry_maps.h"
#include "description/scene_description.h"
#include "facade/building_structure.h"
#include "facade/facade_building.h"
#include "scene/camera.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

// A building on a footprint from data (a city's lot, a CityGML building's, an ALK footprint) in
// `look`, at the data's `loc`: edge 0 of its structure is the footprint's edge `front` (the
// street side), or its longest edge when the data does not say; it stands at height `base`,
// translated to its first corner. The caller sets its ids, and the storeys or eaves height the
// data gives.
ModularBuildingDesc footprintBuilding(const ModularLookDesc &look, const FileLoc &loc, std::vector<Vec2f> footprint,
                                      std::optional<size_t> front, float base);

// The modular buildings of one scene. What they share is made once: each structure and style file
// read (a style's materials checked as it is read), each style's window assemblies built, each
// window and console model a prototype that all its buildings instance.
class ModularBuildings {
  public:
    // The mean albedo of one of the scene's materials, its colour times its diffuse map's mean:
    // what an apron's face (facade/apron_ornament.h) shows, since its baked maps replace the
    // material's. Without one, the material's colour.
    using MaterialAlbedo = std::function<Vec3f(MaterialId)>;

    // `camera` and `builder` outlive this; `masonry` takes the walls' masonry, baked or shaded.
    ModularBuildings(const Camera &camera, RenderSceneBuilder &builder, MasonryOutput masonry,
                     MaterialAlbedo albedo = {});
    ~ModularBuildings();
    ModularBuildings(const ModularBuildings &) = delete;
    ModularBuildings &operator=(const ModularBuildings &) = delete;

    // Runs `add` for the element at `loc`, naming the element in what it throws.
    using ElementGuard = std::function<void(const FileLoc &loc, const std::function<void()> &add)>;

    // Adds the buildings in the elements' order, each with its seed, made in parallel batches: its
    // mesh as a world mesh with the element's object and building ids, a building record, its
    // windows and consoles as instances. Each building's notes (openings left out and why) are
    // appended to `warnings` at its element's place. The first element (in order) that fails
    // throws, through `guard`: InputError at the files' places.
    void add(const std::vector<ModularBuildingDesc> &descs, const std::vector<uint32_t> &seeds,
             const ElementGuard &guard, std::vector<std::string> &warnings);

  private:
    struct LoadedStyle;
    struct Made;
    struct LeftOut;

    // Buildings made at once before they are placed: what bounds the memory their atlases hold.
    static constexpr size_t kModularBatch = 64;

    Made make(const ModularBuildingDesc &desc, uint32_t seed, const BuildingStructure &structure,
              LoadedStyle &style) const;
    void place(const ModularBuildingDesc &desc, Made made, std::vector<std::string> &warnings);

    const BuildingStructure &structure(const std::filesystem::path &file);
    LoadedStyle &style(const std::filesystem::path &file);
    void addInstances(const ModularBuildingDesc &desc, PrototypeId prototype, const std::vector<Transform> &transforms);

    const Camera &camera_;
    CameraRays rays_;
    RenderSceneBuilder &builder_;
    MasonryOutput masonry_;
    MaterialAlbedo albedo_;
    std::map<std::filesystem::path, BuildingStructure> structures_;
    std::map<std::filesystem::path, std::unique_ptr<LoadedStyle>> styles_;
    std::map<const Mesh *, PrototypeId> openingPrototypes_;  // by the style's shared window models
    ConsolePrototypes consoles_;
};

}  // namespace veduta
