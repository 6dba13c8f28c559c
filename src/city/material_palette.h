// Which material each part of a generated building gets (Bilke's GetRandomMaterialSet,
// Bilke 2009, §2 and §4): every building picks one material per category from those the scene
// defines, and a rule's texture attribute names a material or, through its folder, a category.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/material.h"
#include "scene/render_scene.h"

namespace veduta {

inline constexpr size_t kMaterialCategoryCount = size_t(MaterialCategory::Reflection) + 1;

// One building's choice: a material per category. Category None stands for the dark interior
// seen through windows.
struct MaterialSet {
    std::array<MaterialId, kMaterialCategoryCount> byCategory{};
    MaterialId operator[](MaterialCategory c) const { return byCategory[size_t(c)]; }
};

class MaterialPalette {
  public:
    // Reads the builder's materials by category; a category the scene leaves empty gets a plain
    // built-in material, added to the builder.
    explicit MaterialPalette(RenderSceneBuilder &builder);

    MaterialSet choose(uint32_t seed, uint32_t buildingId) const;

    // What a rule's texture attribute ("reflection/AluminiumBrushVert.png") stands for: the
    // material named after the path without its extension if the scene has one, else the
    // category of the path's first folder (wall, window or glass, door, roof, reflection,
    // facade; anything else: material), whose material each building chooses.
    struct TextureChoice {
        MaterialId named = kNoMaterial;
        MaterialCategory category = MaterialCategory::Material;
        MaterialId in(const MaterialSet &set) const { return named != kNoMaterial ? named : set[category]; }
    };
    TextureChoice forTexture(const std::string &texture) const;

  private:
    std::array<std::vector<MaterialId>, kMaterialCategoryCount> candidates_;
    const RenderSceneBuilder *builder_;
};

}  // namespace veduta
