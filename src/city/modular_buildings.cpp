#include "city/modular_buildings.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "core/hash.h"
#include "core/input_file.h"
#include "facade/building_description.h"
#include "facade/facade_building.h"
#include "facade/masonry_atlas.h"
#include "io/image_library.h"
#include "io/mesh_import.h"

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

BuildingStructure readStructure(const ModularBuildingDesc &desc) {
    BuildingStructure structure = parseBuildingStructure(readInputFile(desc.structure), desc.structure.string());
    if (desc.footprint.empty()) return structure;
    if (structure.modules.size() != 1)
        throw InputError(desc.footprintLoc,
                         fmt::format("with a footprint, the structure's one module is the "
                                     "prototype of its pieces; {} has {} modules",
                                     desc.structure.string(), structure.modules.size()));
    std::vector<Vec2d> footprint;
    for (Vec2f p : desc.footprint) footprint.push_back({p.x, p.y});
    return structureOnFootprint(structure.modules[0], footprint, desc.footprintLoc);
}

// The texel that shows the building's nearest point at about one texel a pixel.
double masonryTexel(const Mesh &mesh, const Transform &toWorld, const Camera &camera) {
    Vec3f low(INFINITY), high(-INFINITY);
    for (const Vec3f &p : mesh.positions) {
        Vec3f w = toWorld.applyPoint(p);
        for (int axis = 0; axis < 3; ++axis) {
            low[axis] = std::min(low[axis], w[axis]);
            high[axis] = std::max(high[axis], w[axis]);
        }
    }
    Vec3f nearest;
    for (int axis = 0; axis < 3; ++axis) nearest[axis] = std::clamp(camera.position[axis], low[axis], high[axis]);
    // pixelsSpanned measures from the box's centre: a metre-long box about the nearest point.
    Vec3f half(0.5f / std::sqrt(3.0f));
    double pixelsPerMetre = camera.pixelsSpanned(nearest - half, nearest + half);
    return std::clamp(1 / std::max(pixelsPerMetre, 1e-6), kFinestMasonryTexel, kCoarsestAtlasTexel);
}

// FNV-1a over the pixels' bits, a word of two samples at a time: the name of a baked file.
uint64_t imageHash(const Image &image) {
    uint64_t h = mix64(uint64_t(image.width) << 32 | uint64_t(image.height)) ^ uint64_t(image.channels);
    const std::vector<float> &p = image.pixels;
    for (size_t i = 0; i + 1 < p.size(); i += 2)
        h = (h ^ (uint64_t(std::bit_cast<uint32_t>(p[i])) << 32 | std::bit_cast<uint32_t>(p[i + 1]))) *
            0x100000001b3ull;
    if (p.size() % 2) h = (h ^ std::bit_cast<uint32_t>(p.back())) * 0x100000001b3ull;
    return mix64(h);
}

// Writes the image under the cache once: named by its content, so that a later run with the same
// masonry finds the file, and its converted texture, as they were.
std::filesystem::path bakedFile(const Image &image, const std::string &kind) {
    std::filesystem::path file =
        defaultTextureCacheDirectory() / "facades" / fmt::format("{:016x}-{}.png", imageHash(image), kind);
    if (!std::filesystem::exists(file)) {
        std::filesystem::create_directories(file.parent_path());
        imageLibrary().write(file, image);
    }
    return file;
}

// The building's masonry faces baked into one atlas; their triangles get the atlas's coordinates
// and a copy of their wall material with its maps.
void bakeMasonry(FacadeBuilding &building, double texel, RenderSceneBuilder &builder, const AddTexture &addTexture,
                 uint32_t buildingId) {
    if (building.masonry.empty()) return;
    std::vector<AtlasWall> walls;
    for (const MasonryWall &w : building.masonry) walls.push_back({&w.masonry, &w.face});
    MasonryAtlas atlas = bakeMasonryAtlas(walls, texel, {}, kModularBuildingTexels);
    TextureId diffuse = addTexture(bakedFile(atlas.diffuse, "diffuse"));
    TextureId normal = addTexture(bakedFile(atlas.normal, "normal"));
    TextureId specular = addTexture(bakedFile(atlas.specular, "specular"));

    std::map<MaterialId, MaterialId> mapped;
    Mesh &mesh = building.mesh;
    std::vector<bool> moved(mesh.positions.size(), false);
    for (size_t w = 0; w < building.masonry.size(); ++w) {
        const MasonryWall &wall = building.masonry[w];
        auto [it, fresh] = mapped.try_emplace(wall.material, kNoMaterial);
        if (fresh) {
            Material m = builder.materials().at(wall.material == kNoMaterial ? 0 : wall.material);
            m.name = fmt::format("{} (building {} masonry)", m.name, buildingId);
            m.diffuse = Vec3f(1.0f);  // the atlas holds the colours
            m.diffuseMap = diffuse;
            m.normalMap = normal;
            m.specularMap = specular;
            if (m.specular == Vec3f(0.0f)) m.specular = Vec3f(1.0f);
            m.textureSize = {1.0f, 1.0f};
            it->second = builder.addMaterial(std::move(m));
        }
        for (uint32_t t : wall.triangles) {
            mesh.triangleMaterials[t] = it->second;
            for (int k = 0; k < 3; ++k) {
                uint32_t v = mesh.indices[3 * t + size_t(k)];
                if (moved[v]) continue;
                moved[v] = true;
                mesh.uvs[v] = atlas.uvOf(w, {mesh.uvs[v].x, mesh.uvs[v].y});
            }
        }
    }
}

void addOpenings(FacadeBuilding &building, const ModularBuildingDesc &desc, RenderSceneBuilder &builder) {
    for (OpeningSet &set : building.openingSets) {
        PrototypeId prototype = builder.addPrototype(std::move(set.model));
        for (const Transform &t : set.transforms)
            builder.addInstance({desc.transform * t, prototype, kNoMaterial, desc.objectId, desc.buildingId, 0});
    }
}

void addConsoles(const FacadeBuilding &building, const ModularBuildingDesc &desc, RenderSceneBuilder &builder) {
    std::map<std::string, PrototypeId> prototypes;
    for (const ConsoleSet &set : building.consoles) {
        auto [it, fresh] = prototypes.try_emplace(set.objectFile, 0);
        if (fresh) {
            Mesh model;
            try {
                model = importMesh(desc.style.parent_path() / set.objectFile);
            } catch (const InputError &e) {
                throw InputError(set.loc, e.what());
            }
            model.setMaterial(set.material);
            it->second = builder.addPrototype(std::move(model));
        }
        for (const Transform &t : set.transforms)
            builder.addInstance({desc.transform * t, it->second, kNoMaterial, desc.objectId, desc.buildingId, 0});
    }
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

void generateModularBuilding(const ModularBuildingDesc &desc, uint32_t seed, const Camera &camera,
                             RenderSceneBuilder &builder, const AddTexture &addTexture,
                             std::vector<std::string> &warnings) {
    BuildingStructure structure = readStructure(desc);
    BuildingStyle style = readStyle(desc.style);
    checkMaterials(style, builder);
    MaterialByName material = [&](const std::string &name, const FileLoc &) {
        return name.empty() ? MaterialId(0) : builder.findMaterial(name);
    };
    FacadeBuilding building = buildFacadeBuilding(structure, style, material, seed, desc.buildingId);
    for (const std::string &note : building.notes) warnings.push_back(desc.loc.toString() + ": " + note);
    bakeMasonry(building, masonryTexel(building.mesh, desc.transform, camera), builder, addTexture, desc.buildingId);
    addOpenings(building, desc, builder);
    addConsoles(building, desc, builder);
    builder.recordBuilding(recordOf(structure, building.mesh, desc.transform, desc.buildingId));
    builder.addMesh(building.mesh, desc.transform, desc.objectId, desc.buildingId);
}

}  // namespace veduta
