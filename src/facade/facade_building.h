// A whole Finkenzeller building from its structure and its style (digest-001 §1's pipeline:
// world model → intermediate model → geometry; L1556, L1601–1652): per storey the floor plan of
// the modules that reach it, its features and elements (corners, walls, ZWE), one opening per
// wall with its casing, frame and pane, the bands swept as cornices with their consoles, and per
// module the general roof, merged at T-junctions. Walls are coarse: a wall element is its
// rectangle less its openings, however many bricks it shows; the masonry is handed out per wall
// face, for baking into textures (masonry_atlas.h), with wall coordinates as texture coordinates.
//
// Choices where the thesis is open:
// * Storeys: storey s is the modules with more than s storeys; the modules of one storey that
//   docks join make one floor plan each (a tower rising from a wing is a plan of its own), the
//   docks placing them as the ground storey's plan does. The ground storey must be one plan.
// * Roof seams (Def 4.12's "connected"): an edge is connected when a docked neighbour at least as
//   high covers all of it; a lower neighbour leaves the wall above it free, so a flat roof gets its
//   parapet there and a gable its wall.
// * Windows under a neighbour's roof (L1608, §8 row 19): an opening whose sill lies below the roof
//   of another module just outside the wall (at its two lower corners and its middle) is dropped,
//   and the building's notes say which and why.
// * An opening that does not fit its wall element is dropped with a note too, rather than
//   shrunk: the style asked for that size.
// * A band run is swept with the cornice of its first element's band; bands of other styles
//   that meet it at the same heights are one run (findBands), so they share that cornice.
// * Masonry is laid per wall face: one module edge (or PP edge) and one resolved masonry style,
//   over all storeys that show it, so that courses run on from storey to storey. The building
//   checks each wall's masonry and hands out its recipe; the stones are laid by whoever needs them
//   (a bake, or a shader when a ray first meets the wall).
// * Gable walls above the eaves are the roof's interface faces, in the style's roof-side material.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/vecmath.h"
#include "facade/building_structure.h"
#include "facade/building_style.h"
#include "facade/cornice_run.h"
#include "facade/masonry.h"
#include "scene/mesh.h"

namespace veduta {

// One wall face's masonry, to be baked or shaded: the face in its own coordinates (x metres along
// the wall from `origin`, y = world z), its openings cut out, and the triangles of the building's
// mesh that show it, whose texture coordinates are those wall coordinates.
struct MasonryWall {
    WallFace face;
    // Stones are laid from `recipe` when they are needed (layMasonryWalls, a MasonryShader); until
    // then `masonry` is empty. A wall of a relief alone has no recipe.
    MasonryRecipe recipe;
    Masonry masonry;
    MaterialId material = kNoMaterial;  // the wall material the baked maps belong to
    std::vector<uint32_t> triangles;
};

// An opening's casing, frame, pane and reveal, the same wherever its window style and materials
// are: one model in the opening's frame (x along the wall from the coarse opening's lower left
// corner, z up, -y out of the wall), one instance per transform (the thesis's window assemblies
// as instances, digest §9).
struct OpeningSet {
    std::shared_ptr<const Mesh> model;  // shared by every building built with the same WindowAssemblies
    std::vector<Transform> transforms;
};

// A window style's assembly in given materials: the model of its opening (as OpeningSet's) and
// the hole it needs in the wall, from the coarse opening's lower left corner.
struct WindowAssembly {
    std::shared_ptr<const Mesh> model;
    std::vector<Vec2d> hole;
    // The relief of the apron below it (apron_ornament.h), when its style has one: as wide as the
    // hole, to the nearest relief cell.
    std::shared_ptr<const Image> apron;
};

// The window assemblies of one style, built once for all the buildings of that style: a casing's
// exact Booleans cost more than the rest of a building's walls. Keep one beside each style
// object; buildFacadeBuilding checks that it is always given with the same style. Buildings may
// be built in parallel with one WindowAssemblies.
class WindowAssemblies {
  public:
    using Key = std::pair<const WindowStyle *, std::array<MaterialId, 7>>;
    // The assembly for `key`, made by `make` the first time. `style` owns the key's window style.
    const WindowAssembly &get(const BuildingStyle &style, const Key &key, const std::function<WindowAssembly()> &make);

  private:
    std::mutex mutex_;
    const BuildingStyle *style_ = nullptr;
    std::map<Key, WindowAssembly> built_;
};

struct FacadeBuilding {
    Mesh mesh;  // walls, cornices, roofs; world metres; flat normals
    std::vector<MasonryWall> masonry;
    std::vector<OpeningSet> openingSets;
    std::vector<ConsoleSet> consoles;
    std::vector<std::string> notes;  // what was left out, how often and why
    size_t openings = 0;             // placed
};

// Scene materials by the names the style gives; "" is the default material.
using MaterialByName = std::function<MaterialId(const std::string &name, const FileLoc &loc)>;

inline constexpr size_t kFacadeElementLimit = 200000;  // wall elements over all storeys

// Builds the building. `seed` and `buildingId` make its masonry (every stone's size and colour);
// its window assemblies come from, or go to, `windows`, the style's. Throws InputError at the
// structure's or the style's place when they do not fit together (a binding to a missing module,
// a plan that does not close, a cornice that cannot be swept).
FacadeBuilding buildFacadeBuilding(const BuildingStructure &structure, const BuildingStyle &style,
                                   const MaterialByName &material, uint32_t seed, uint32_t buildingId,
                                   WindowAssemblies &windows);
// The same with window assemblies of its own.
FacadeBuilding buildFacadeBuilding(const BuildingStructure &structure, const BuildingStyle &style,
                                   const MaterialByName &material, uint32_t seed, uint32_t buildingId);

}  // namespace veduta
