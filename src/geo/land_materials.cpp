#include "geo/land_materials.h"

#include <string>

#include <fmt/format.h>

#include "core/hash.h"
#include "geo/pavement_texture.h"
#include "geo/terrain_texture.h"

namespace veduta {

namespace {

// The colour each land class has without a texture, and its texture's base colour.
Material plainLandMaterial(LandClass c) {
    std::string name = fmt::format("land/{}", landClassName(c));
    switch (c) {
    case LandClass::Road:
    case LandClass::CityStreet: return Material::lambertian(name, {0.13f, 0.13f, 0.14f});  // under the streets
    case LandClass::Path: return Material::lambertian(name, {0.42f, 0.38f, 0.31f});
    case LandClass::Rail: return Material::lambertian(name, {0.27f, 0.24f, 0.22f});
    case LandClass::Settlement: return Material::lambertian(name, {0.21f, 0.24f, 0.14f});  // gardens and yards
    case LandClass::Park: return Material::lambertian(name, {0.12f, 0.22f, 0.07f});
    case LandClass::Farmland: return Material::lambertian(name, {0.34f, 0.27f, 0.16f});
    case LandClass::Grassland: return Material::lambertian(name, {0.13f, 0.23f, 0.06f});
    case LandClass::Forest: return Material::lambertian(name, {0.08f, 0.09f, 0.04f});
    case LandClass::Shrubs:
    case LandClass::TreeRow:
    case LandClass::Hedge: return Material::lambertian(name, {0.1f, 0.15f, 0.06f});
    case LandClass::Water:
    case LandClass::River: {
        Material water = Material::lambertian(name, {0.015f, 0.03f, 0.035f});
        water.specular = Vec3f(0.25f);
        water.shininess = 800;
        water.reflectivity = Vec3f(0.04f);
        return water;
    }
    case LandClass::Building: return Material::lambertian(name, {0.3f, 0.28f, 0.27f});  // a footprint seen from above
    case LandClass::Other:
    case LandClass::Parcel: break;
    }
    return Material::lambertian("land/bare", {0.2f, 0.24f, 0.11f});
}

Material plainPavementMaterial(Pavement pavement, int tracks) {
    std::string name = fmt::format("land/{}", pavementName(pavement));
    if (pavement == Pavement::Ballast && tracks > 1) name += fmt::format("-{}", tracks);
    switch (pavement) {
    case Pavement::Asphalt: return Material::lambertian(name, {0.13f, 0.13f, 0.14f});
    case Pavement::Cobbles: return Material::lambertian(name, {0.2f, 0.18f, 0.16f});
    case Pavement::Concrete: return Material::lambertian(name, {0.36f, 0.35f, 0.33f});
    case Pavement::Gravel: return Material::lambertian(name, {0.42f, 0.38f, 0.31f});
    case Pavement::Ballast: return Material::lambertian(name, {0.27f, 0.24f, 0.22f});
    }
    return Material::lambertian(name, {0.13f, 0.13f, 0.14f});
}

// Whether a land class's ground is textured: water stays a dark mirror, the ground under
// city streets is hidden, and traffic areas and footprints keep their plain colour.
bool textured(LandClass c) {
    switch (c) {
    case LandClass::Water:
    case LandClass::River:
    case LandClass::CityStreet:
    case LandClass::Road:
    case LandClass::Path:
    case LandClass::Rail:
    case LandClass::Building: return false;
    default: return true;
    }
}

void readInMetres(Material &m) { m.textureSize = Vec2f{1 / kLandTileMetres, 1 / kLandTileMetres}; }

}  // namespace

LandMaterials::LandMaterials(RenderSceneBuilder &builder, AddProcedural addProcedural,
                             std::shared_ptr<const HeightGrid> grid, LocalFrame frame,
                             std::shared_ptr<const ShoreDistance> shore, uint32_t seed) :
    builder_(builder),
    addProcedural_(std::move(addProcedural)),
    grid_(std::move(grid)),
    frame_(frame),
    shore_(std::move(shore)),
    seed_(seed) {}

MaterialId LandMaterials::land(LandClass c) {
    auto found = land_.find(c);
    if (found != land_.end()) return found->second;
    Material m = plainLandMaterial(c);
    MaterialId id = builder_.findMaterial(m.name);
    if (id == kNoMaterial) {
        if (addProcedural_ && textured(c)) {
            m.diffuseMap = addProcedural_(std::make_shared<TerrainTexture>(c, m.diffuse, grid_, frame_, shore_,
                                                                           hashValues({seed_, uint32_t(c)})));
            m.diffuse = Vec3f(1);
            readInMetres(m);
        }
        id = builder_.addMaterial(std::move(m));
    }
    land_[c] = id;
    return id;
}

MaterialId LandMaterials::pavement(Pavement pavement, int tracks) {
    if (pavement != Pavement::Ballast) tracks = 1;
    auto key = std::make_pair(pavement, tracks);
    auto found = pavements_.find(key);
    if (found != pavements_.end()) return found->second;
    Material m = plainPavementMaterial(pavement, tracks);
    MaterialId id = builder_.findMaterial(m.name);
    if (id == kNoMaterial) {
        if (addProcedural_) {
            uint32_t seed = hashValues({seed_, 0x70617665u, uint32_t(pavement)});
            m.diffuseMap =
                addProcedural_(std::make_shared<PavementTexture>(pavement, PavementMap::Colour, seed, tracks));
            m.normalMap =
                addProcedural_(std::make_shared<PavementTexture>(pavement, PavementMap::Normal, seed, tracks));
            m.diffuse = Vec3f(1);
            readInMetres(m);
        }
        id = builder_.addMaterial(std::move(m));
    }
    pavements_[key] = id;
    return id;
}

// Road paint: white, with a faint sheen from its glass beads.
MaterialId LandMaterials::marking() {
    Material paint = Material::lambertian("land/marking", {0.72f, 0.72f, 0.7f});
    paint.specular = Vec3f(0.04f);
    paint.shininess = 60;
    return builder_.findOrAddMaterial(std::move(paint));
}

MaterialId LandMaterials::track(TrackSurface surface) {
    if (surface == TrackSleeper)
        return builder_.findOrAddMaterial(Material::lambertian("land/sleeper", {0.42f, 0.41f, 0.39f}));
    Material steel = Material::lambertian("land/rail_steel", {0.22f, 0.15f, 0.11f});
    steel.specular = Vec3f(0.25f);
    steel.shininess = 80;
    return builder_.findOrAddMaterial(std::move(steel));
}

}  // namespace veduta
