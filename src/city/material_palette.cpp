#include "city/material_palette.h"

#include <filesystem>

#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

namespace {

// Stand-ins for a scene that defines no material of a category: Gründerzeit plaster, sandstone,
// dark oak, clear glass, zinc, slate, and the dark of a room seen from the street.
Material builtInMaterial(MaterialCategory category) {
    switch (category) {
    case MaterialCategory::Facade:
    case MaterialCategory::Wall: return Material::lambertian("veduta/plaster", {0.72f, 0.64f, 0.5f});
    case MaterialCategory::Roof: return Material::lambertian("veduta/slate", {0.16f, 0.17f, 0.19f});
    case MaterialCategory::Material: return Material::lambertian("veduta/sandstone", {0.66f, 0.58f, 0.46f});
    case MaterialCategory::Door: return Material::lambertian("veduta/oak", {0.22f, 0.13f, 0.07f});
    case MaterialCategory::Window: {
        Material glass;
        glass.name = "veduta/glass";
        glass.glass = true;
        return glass;
    }
    case MaterialCategory::Reflection: {
        Material zinc = Material::lambertian("veduta/zinc", {0.35f, 0.36f, 0.38f});
        zinc.reflectivity = Vec3f(0.4f);
        return zinc;
    }
    case MaterialCategory::None: break;
    }
    return Material::lambertian("veduta/interior", {0.03f, 0.03f, 0.035f});
}

MaterialCategory categoryOfFolder(const std::string &folder) {
    if (folder == "wall") return MaterialCategory::Wall;
    if (folder == "window" || folder == "glass") return MaterialCategory::Window;
    if (folder == "door" || folder == "doors") return MaterialCategory::Door;
    if (folder == "roof") return MaterialCategory::Roof;
    if (folder == "reflection") return MaterialCategory::Reflection;
    if (folder == "facade" || folder == "facades") return MaterialCategory::Facade;
    return MaterialCategory::Material;
}

}  // namespace

MaterialPalette::MaterialPalette(RenderSceneBuilder &builder) : builder_(&builder) {
    const std::vector<Material> &materials = builder.materials();
    for (MaterialId id = 0; id < materials.size(); ++id) {
        const Material &m = materials[id];
        if (m.category != MaterialCategory::None) candidates_[size_t(m.category)].push_back(id);
    }
    // The interior is the material called "interior", not every material without a category.
    if (MaterialId interior = builder.findMaterial("interior"); interior != kNoMaterial)
        candidates_[size_t(MaterialCategory::None)].push_back(interior);
    for (size_t c = 0; c < kMaterialCategoryCount; ++c) {
        if (!candidates_[c].empty()) continue;
        Material stand = builtInMaterial(MaterialCategory(c));
        candidates_[c].push_back(builder.findOrAddMaterial(stand));
    }
}

MaterialSet MaterialPalette::choose(uint32_t seed, uint32_t buildingId) const {
    MaterialSet set;
    for (size_t c = 0; c < kMaterialCategoryCount; ++c) {
        const auto &candidates = candidates_[c];
        uint32_t pick = hashValues({seed, buildingId, streamTag(RandomStream::MaterialPalette), uint32_t(c)});
        set.byCategory[c] = candidates[pick % candidates.size()];
    }
    return set;
}

MaterialPalette::TextureChoice MaterialPalette::forTexture(const std::string &texture) const {
    std::filesystem::path path(texture);
    TextureChoice choice;
    choice.named = builder_->findMaterial((path.parent_path() / path.stem()).generic_string());
    choice.category = categoryOfFolder(path.has_parent_path() ? path.begin()->string() : "");
    return choice;
}

}  // namespace veduta
