// Generating a procedural building from its footprint (Bilke's BuildingGenerator,
// Bilke 2009, §2.4): one start shape per wall, each derived with the split grammar; models become
// instances of shared prototypes, walls are baked with planar texture coordinates that run on
// across neighbouring pieces and around the corners, and a roof of the settings' type
// (roof_choice.h) closes the top.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "city/assets.h"
#include "city/building_settings.h"
#include "city/console_prototypes.h"
#include "city/derivation.h"
#include "city/footprint.h"
#include "city/masonry_maps.h"
#include "city/material_palette.h"
#include "city/rule_cornices.h"
#include "city/start_shapes.h"
#include "core/error.h"
#include "facade/facade_building.h"
#include "facade/masonry_atlas.h"
#include "scene/camera.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

struct BuildingSpec {
    uint32_t id = 0;  // the building's stable identity: its random choices and its id pass
    ObjectId objectId = 0;
    Footprint footprint;     // normalised (counter-clockwise)
    SettingsStack settings;  // lot > block > city > rule file > defaults
    bool coarse = false;     // seen from far: one plain quad a wall and the roof, no rules derived
    std::vector<bool>
        partyEdges;  // one per footprint edge, or empty: walls built against a neighbour's (party_walls.h)
};

// A lone facade (the Facade Editor's preview, Bilke 2009, §3.2): a start symbol on a width × height
// rectangle placed by `facadeToWorld` (facade frame: right, up, out).
struct FacadeSpec {
    uint32_t id = 0;
    ObjectId objectId = 0;
    std::string startSymbol;
    float width = 0, height = 0;
    Transform facadeToWorld;
    SettingsStack settings;
};

struct BuildingStats {
    size_t terminals = 0;
    size_t instances = 0;
    size_t bakedTriangles = 0;
};

// Runs `build` for the building that the input describes at `loc` (its lot, OSM way or
// <building>): an InputError from its rules, a derivation limit hit on this building's size,
// is given the building's place in front, since that is where the user can look.
template <typename Build>
void buildAt(const FileLoc &loc, Build &&build) {
    try {
        build();
    } catch (const InputError &e) {
        throw InputError(loc, std::string("this building cannot be built: ") + e.what());
    }
}

class BuildingGenerator {
  public:
    static constexpr size_t kMaxSurfaces = 4;  // checked against the library when constructed
    // A model in a building's materials: one prototype of the scene.
    struct PrototypeKey {
        uint32_t model = 0;
        std::array<MaterialId, kMaxSurfaces> materials{};
        bool operator==(const PrototypeKey &) const = default;
    };

    // A building made and not yet in the scene: what generate() adds to the builder.
    struct MadeBuilding {
        ObjectId objectId = 0;
        uint32_t id = 0;
        Mesh mesh;  // walls and roof, welded
        struct Placement {
            Transform objectToWorld;
            PrototypeKey prototype;
        };
        std::vector<Placement> instances;      // the models, in the order the rules placed them
        std::optional<BuildingRecord> record;  // none for a lone facade
        BuildingStats stats;
        // The walls of the rules' <Masonry> models (their stones dropped once baked) and their atlas.
        std::vector<MasonryWall> masonry;
        std::vector<std::pair<uint32_t, const MasonryRule *>> masonryFacades;  // each wall's facade edge, rule
        std::optional<MasonryAtlas> masonryMaps;                               // baked
        std::shared_ptr<const MasonryShader> masonryShader;                    // or shaded
        std::vector<ConsoleSet> consoles;  // under the rules' <Cornice> sweeps, in the mesh
    };

    // Throws InputError at a rule file's <Masonry> that names no wall model, or <Cornice> that
    // names one.
    BuildingGenerator(const Grammar &grammar, const AssetLibrary &assets, RenderSceneBuilder &builder, uint32_t seed,
                      const DerivationLimits &limits = {});

    // What the rules' <Masonry> needs: the camera its texels are matched to, and where the
    // masonry goes, baked or shaded. Without it (a library caller), those walls keep their
    // model's texture, and the first building says so.
    void bakeMasonryWith(const Camera &camera, MasonryOutput masonry);

    // Emits one building into the builder: add(make(building)). Warnings are appended as
    // "file:line:col: message"; problems in the rules or settings throw InputError.
    BuildingStats generate(const BuildingSpec &building, std::vector<std::string> &warnings);
    BuildingStats generateFacade(const FacadeSpec &facade, std::vector<std::string> &warnings);

    // The building, made without touching the builder: many threads may make buildings at
    // once (each with warnings of its own) while nothing adds to the builder. Throws InputError
    // as generate does, with the warnings before the error appended.
    MadeBuilding make(const BuildingSpec &building, std::vector<std::string> &warnings) const;
    // Adds a made building to the builder: its prototypes (each new one when first used, so
    // buildings added in one order give one scene), instances, mesh and record; the mesh
    // appended to `merged` instead when that is given (distant buildings share one).
    BuildingStats add(MadeBuilding &&building, Mesh *merged = nullptr);

  private:
    struct PrototypeKeyHash {
        size_t operator()(const PrototypeKey &key) const;
    };

    // What every facade of one building shares.
    struct BuildingContext {
        uint32_t id = 0;
        ObjectId objectId = 0;
        BuildingHeights heights;
        BuildingProperties properties;
        MaterialSet materials;
    };
    BuildingContext contextFor(uint32_t id, ObjectId objectId, const SettingsStack &settings) const;
    void emitFacade(const BuildingContext &building, const StartShape &start, size_t facade, float alongPerimeter,
                    Mesh &baked, MadeBuilding &made, std::vector<CornicePlace> &cornices,
                    std::vector<std::string> &warnings) const;
    const CorniceRule *corniceOf(const Terminal &terminal) const;
    void addCornices(const std::vector<CornicePlace> &places, const std::vector<StartShape> &facades, Mesh &baked,
                     MadeBuilding &made) const;
    Terminal plainWallOf(const StartShape &start) const;
    // The whole start shape as the plain wall model, in the building's wall material or in
    // `material` (a party wall's).
    void addPlainWall(const BuildingContext &building, const StartShape &start, float alongPerimeter, Mesh &baked,
                      std::optional<MaterialId> material = std::nullopt) const;
    PrototypeId prototypeFor(const PrototypeKey &key);
    PrototypeKey keyFor(const Terminal &terminal, const MaterialSet &materials) const;
    void addWallPiece(const Asset &model, const Transform &modelToFacade, const Transform &facadeToWorld,
                      float alongPerimeter, const Terminal &terminal, const PrototypeKey &key, Mesh &baked) const;
    void addRoof(const BuildingSpec &building, const BuildingContext &context, Mesh &baked, MadeBuilding &made,
                 std::vector<std::string> &warnings) const;
    const MasonryRule *masonryOf(uint32_t model, const std::string &facade) const;
    void addMasonryPiece(const Asset &model, const Transform &modelToFacade, const StartShape &start,
                         const PrototypeKey &key, const MasonryRule &rule, Mesh &baked, MadeBuilding &made) const;
    void bakeMasonry(const BuildingContext &building, Mesh &baked, MadeBuilding &made,
                     std::vector<std::string> &warnings) const;

    const Grammar &grammar_;
    const AssetLibrary &assets_;
    RenderSceneBuilder &builder_;
    MaterialPalette palette_;
    uint32_t seed_;
    DerivationLimits limits_;
    uint32_t plainWall_;    // Wall0, for walls the rules have no start rule for
    MaterialId partyWall_;  // party_wall, the scene's or a rough grey plaster (party_walls.h)
    std::unordered_map<uint32_t, std::vector<const MasonryRule *>> masonryModels_;  // the rules' <Masonry>
    std::unordered_map<uint32_t, std::vector<const CorniceRule *>> corniceModels_;  // and <Cornice>
    ConsolePrototypes consolePrototypes_;
    struct MasonryBaking {
        const Camera *camera;
        CameraRays rays;
        MasonryOutput output;
    };
    std::optional<MasonryBaking> masonryBaking_;
    mutable std::atomic<bool> masonryUnbakedSaid_ = false;
    std::unordered_map<PrototypeKey, PrototypeId, PrototypeKeyHash> prototypes_;
    // What each texture of the rules stands for, found when first needed by any thread.
    mutable std::mutex textureMutex_;
    mutable std::unordered_map<const std::string *, MaterialPalette::TextureChoice> textureChoices_;
};

}  // namespace veduta
