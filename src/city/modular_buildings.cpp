#include "city/modular_buildings.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "city/masonry_maps.h"
#include "city/prism_building.h"
#include "core/check.h"
#include "core/input_file.h"
#include "facade/building_description.h"
#include "facade/facade_building.h"

namespace veduta {

namespace {

// The style names its masonry and cornice files relative to itself.
BuildingStyle readStyle(const std::filesystem::path &file) {
    std::filesystem::path folder = file.parent_path();
    return parseBuildingStyle(readInputFile(file), file.string(), [&](const std::string &name, const FileLoc &loc) {
        std::filesystem::path named = folder / name;
        try {
            return readInputFile(named);
        } catch (const InputError &e) {
            throw InputError(loc, e.what());
        }
    });
}

// With a footprint, the structure's one module is the prototype of its pieces.
void checkPrototype(const BuildingStructure &structure, const ModularBuildingDesc &desc) {
    if (desc.footprint.empty() || structure.modules.size() == 1) return;
    throw InputError(desc.fromData ? desc.structureLoc : desc.footprintLoc,
                     fmt::format("with a footprint, the structure's one module is the "
                                 "prototype of its pieces; {} has {} modules",
                                 desc.structure.string(), structure.modules.size()));
}

// The structure on the element's footprint, if it gives one, with the storeys the data asks for;
// a count or height beyond kStructureStoreyLimit storeys is built at the limit and said in `notes`.
BuildingStructure placedStructure(const BuildingStructure &structure, const ModularBuildingDesc &desc,
                                  std::vector<std::string> &notes) {
    if (desc.footprint.empty()) return structure;
    std::vector<Vec2d> footprint;
    for (Vec2f p : desc.footprint) footprint.push_back({p.x, p.y});
    BuildingStructure placed = structureOnFootprint(structure.modules[0], footprint, desc.footprintLoc);
    const std::vector<double> &written = structure.modules[0].storeyHeights;
    if (desc.storeys) {
        if (*desc.storeys > kStructureStoreyLimit)
            notes.push_back(fmt::format("the data counts {} storeys, more than a building may have; built with {}",
                                        *desc.storeys, kStructureStoreyLimit));
        refitStoreys(placed, std::clamp<size_t>(*desc.storeys, 1, kStructureStoreyLimit));
    } else if (desc.eaves) {
        size_t count = storeysNearest(written, *desc.eaves);
        if (count == kStructureStoreyLimit)
            notes.push_back(
                fmt::format("eaves {:.1f} m high would take more storeys than a building may have; "
                            "built with {}",
                            *desc.eaves, kStructureStoreyLimit));
        refitStoreys(placed, count);
    }
    return placed;
}

// The edge of a footprint from data that faces the street when the data does not say: the longest.
size_t longestEdge(const std::vector<Vec2f> &points) {
    auto edgeLength = [&](size_t i) {
        Vec2f d = points[(i + 1) % points.size()] - points[i];
        return std::hypot(d.x, d.y);
    };
    size_t longest = 0;
    for (size_t i = 1; i < points.size(); ++i)
        if (edgeLength(i) > edgeLength(longest)) longest = i;
    return longest;
}

// Whether `rule` picks the building, seen from `camera`: its modules' box from the ground to the
// eaves, placed by `toWorld`.
bool pickedAsCoarse(const CoarseRule &rule, const Camera &camera, const BuildingStructure &structure,
                    const Transform &toWorld) {
    Vec3f low(INFINITY), high(-INFINITY);
    for (const ModuleStructure &m : structure.modules)
        for (Vec2d p : m.module.outline)
            for (double z : {0.0, m.height()}) {
                Vec3f q = toWorld.applyPoint({float(p.x), float(p.y), float(z)});
                low = {std::min(low.x, q.x), std::min(low.y, q.y), std::min(low.z, q.z)};
                high = {std::max(high.x, q.x), std::max(high.y, q.y), std::max(high.z, q.z)};
            }
    return rule.isCoarse(camera, low, high);
}

// The coarse building: each module a prism up to its eaves (prismBuilding), its walls in its
// middle storey's wall material (what most of a front shows) and its flat top in its top storey's
// roof material (as resolveStyle gives them); the floor, hidden on the ground, as its walls.
Mesh coarseBlock(const BuildingStructure &structure, const BuildingStyle &style, const MaterialByName &material) {
    Mesh block;
    for (const ModuleStructure &m : structure.modules) {
        std::vector<Vec2f> outline;
        for (Vec2d p : m.module.outline) outline.push_back({float(p.x), float(p.y)});
        Mesh prism = prismBuilding(outline, 0, float(m.height()), {1, 1});
        const int middle = int(m.storeyHeights.size()) / 2, top = int(m.storeyHeights.size()) - 1;
        MaterialId wall =
            material(resolveStyle(style, m.name, structure.storeyRole(middle)).material(StylePart::Wall), {});
        MaterialId roof =
            material(resolveStyle(style, m.name, structure.storeyRole(top)).material(StylePart::Roof), {});
        for (MaterialId &t : prism.triangleMaterials) t = t == PrismRoof ? roof : wall;
        block.append(prism, Transform());
    }
    return block;
}

// Every material a style names is the scene's, said at the style that names it.
void checkMaterials(const BuildingStyle &style, const RenderSceneBuilder &builder) {
    for (const Style &s : style.styles)
        for (size_t p = 0; p < kStylePartCount; ++p)
            if (s.materials[p] && !s.materials[p]->empty() && builder.findMaterial(*s.materials[p]) == kNoMaterial)
                throw InputError(s.loc,
                                 fmt::format("style '{}': the scene has no material called '{}' (for its {})", s.name,
                                             *s.materials[p], stylePartName(StylePart(p))));
}

BuildingRecord recordOf(const BuildingStructure &structure, const Mesh &mesh, const Transform &toWorld,
                        uint32_t buildingId) {
    BuildingRecord record;
    record.id = buildingId;
    record.base = INFINITY;
    record.ridge = -INFINITY;
    for (const Vec3f &p : mesh.positions) {
        float z = toWorld.applyPoint(p).z;
        record.base = std::min(record.base, z);
        record.ridge = std::max(record.ridge, z);
    }
    double eaves = 0;
    for (const ModuleStructure &m : structure.modules) eaves = std::max(eaves, m.height());
    record.eaves = toWorld.applyPoint({0, 0, float(eaves)}).z;
    return record;
}

}  // namespace

struct ModularBuildings::LoadedStyle {
    BuildingStyle style;
    WindowAssemblies windows;
};

// One building made, before anything of it is in the scene.
struct ModularBuildings::Made {
    std::string leftOut;  // a footprint from data that no partition fits: why
    BuildingStructure structure;
    FacadeBuilding building;
    std::optional<MasonryAtlas> atlas;            // baked
    std::shared_ptr<const MasonryShader> shader;  // or shaded
};

// Footprints from data left out, counted: a district's worth of them is one warning, not thousands.
struct ModularBuildings::LeftOut {
    size_t count = 0;
    std::string first;

    void add(const std::string &why) {
        if (count++ == 0) first = why;
    }
    void warn(std::vector<std::string> &warnings) const {
        if (count == 0) return;
        warnings.push_back(
            fmt::format("{} footprint{} from data left out: no partition into modules fits {} "
                        "(the first: {})",
                        count, count == 1 ? "" : "s", count == 1 ? "it" : "them", first));
    }
};

ModularBuildingDesc footprintBuilding(const ModularLookDesc &look, const FileLoc &loc, std::vector<Vec2f> footprint,
                                      std::optional<size_t> front, float base) {
    ModularBuildingDesc desc;
    desc.loc = desc.footprintLoc = loc;
    desc.structure = look.structure;
    desc.style = look.style;
    desc.structureLoc = look.structureLoc;
    desc.styleLoc = look.styleLoc;
    desc.fromData = true;
    std::rotate(footprint.begin(), footprint.begin() + long(front.value_or(longestEdge(footprint))), footprint.end());
    const Vec2f corner = footprint.front();
    for (Vec2f &p : footprint) p = p - corner;
    desc.footprint = std::move(footprint);
    desc.transform = Transform::translate({corner.x, corner.y, base});
    return desc;
}

ModularBuildings::ModularBuildings(const Camera &camera, RenderSceneBuilder &builder, MasonryOutput masonry,
                                   MaterialAlbedo albedo) :
    camera_(camera),
    rays_(camera),
    builder_(builder),
    masonry_(std::move(masonry)),
    albedo_(std::move(albedo)),
    consoles_(builder) {}

ModularBuildings::~ModularBuildings() = default;

void ModularBuildings::add(const std::vector<ModularBuildingDesc> &descs, const std::vector<uint32_t> &seeds,
                           const ElementGuard &guard, std::vector<std::string> &warnings) {
    VEDUTA_CHECK(descs.size() == seeds.size(), "a seed for every modular building");
    LeftOut leftOut;
    for (size_t first = 0; first < descs.size(); first += kModularBatch) {
        const size_t end = std::min(descs.size(), first + kModularBatch);
        std::vector<std::optional<Made>> made(end - first);
        std::vector<std::exception_ptr> errors(end - first);
        // The files first, in order, on this thread: the caches they fill are then only read.
        std::vector<std::pair<const BuildingStructure *, LoadedStyle *>> inputs(end - first);
        for (size_t i = first; i < end; ++i) try {
                inputs[i - first] = {&structure(descs[i].structure), &style(descs[i].style)};
            } catch (...) {
                errors[i - first] = std::current_exception();
            }
        tbb::parallel_for(first, end, [&](size_t i) {
            if (errors[i - first]) return;
            try {
                made[i - first] = make(descs[i], seeds[i], *inputs[i - first].first, *inputs[i - first].second);
            } catch (...) {
                errors[i - first] = std::current_exception();
            }
        });
        for (size_t i = first; i < end; ++i) {
            if (errors[i - first]) guard(descs[i].loc, [&] { std::rethrow_exception(errors[i - first]); });
            if (!made[i - first]->leftOut.empty()) leftOut.add(made[i - first]->leftOut);
            else guard(descs[i].loc, [&] { place(descs[i], std::move(*made[i - first]), warnings); });
        }
    }
    leftOut.warn(warnings);
}

ModularBuildings::Made ModularBuildings::make(const ModularBuildingDesc &desc, uint32_t seed,
                                              const BuildingStructure &structure, LoadedStyle &style) const {
    Made made;
    checkPrototype(structure, desc);
    std::vector<std::string> notes;
    try {
        made.structure = placedStructure(structure, desc, notes);
    } catch (const InputError &e) {
        if (!desc.fromData) throw;
        made.leftOut = e.what();
        return made;
    }
    MaterialByName material = [&](const std::string &name, const FileLoc &) {
        return name.empty() ? MaterialId(0) : builder_.findMaterial(name);
    };
    if (desc.coarse && pickedAsCoarse(*desc.coarse, camera_, made.structure, desc.transform)) {
        made.building.mesh = coarseBlock(made.structure, style.style, material);
        made.building.notes = std::move(notes);
        return made;
    }
    made.building = buildFacadeBuilding(made.structure, style.style, material, seed, desc.buildingId, style.windows);
    made.building.notes.insert(made.building.notes.begin(), notes.begin(), notes.end());
    // A relief alone (an apron's) shows its material's albedo; the atlas replaces the material's.
    for (MasonryWall &wall : made.building.masonry)
        if (wall.masonry.relief && !wall.recipe.lay)
            wall.masonry.mortarColour =
                albedo_ ? albedo_(wall.material) : builder_.materials().at(wall.material).diffuse;
    if (masonry_.procedural) made.shader = shadeMasonry(made.building.mesh, made.building.masonry);
    else made.atlas = bakeMasonryMaps(made.building.mesh, made.building.masonry, desc.transform, rays_, camera_);
    return made;
}

void ModularBuildings::place(const ModularBuildingDesc &desc, Made made, std::vector<std::string> &warnings) {
    FacadeBuilding &building = made.building;
    for (const std::string &note : building.notes) warnings.push_back(desc.loc.toString() + ": " + note);
    if (made.atlas)
        addMasonryMaps(building.mesh, building.masonry, std::move(*made.atlas), builder_, masonry_.addImage,
                       desc.buildingId);
    if (made.shader)
        addMasonryShader(building.mesh, building.masonry, std::move(made.shader), builder_, masonry_.addProcedural,
                         desc.buildingId);
    for (const OpeningSet &set : building.openingSets) {
        auto [it, fresh] = openingPrototypes_.try_emplace(set.model.get(), 0);
        if (fresh) it->second = builder_.addPrototype(*set.model);
        addInstances(desc, it->second, set.transforms);
    }
    for (const ConsoleSet &set : building.consoles)
        addInstances(desc, consoles_.get(desc.style.parent_path() / set.objectFile, set), set.transforms);
    builder_.recordBuilding(recordOf(made.structure, building.mesh, desc.transform, desc.buildingId));
    builder_.addMesh(building.mesh, desc.transform, desc.objectId, desc.buildingId);
}

const BuildingStructure &ModularBuildings::structure(const std::filesystem::path &file) {
    auto it = structures_.find(file);
    if (it == structures_.end())
        it = structures_.emplace(file, parseBuildingStructure(readInputFile(file), file.string())).first;
    return it->second;
}

ModularBuildings::LoadedStyle &ModularBuildings::style(const std::filesystem::path &file) {
    auto it = styles_.find(file);
    if (it == styles_.end()) {
        auto loaded = std::make_unique<LoadedStyle>();
        loaded->style = readStyle(file);
        checkMaterials(loaded->style, builder_);
        it = styles_.emplace(file, std::move(loaded)).first;
    }
    return *it->second;
}

void ModularBuildings::addInstances(const ModularBuildingDesc &desc, PrototypeId prototype,
                                    const std::vector<Transform> &transforms) {
    for (const Transform &t : transforms)
        builder_.addInstance({desc.transform * t, prototype, kNoMaterial, desc.objectId, desc.buildingId, 0});
}

}  // namespace veduta
