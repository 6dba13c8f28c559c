// The built-in facade models of Bilke's Gründerzeit rule set: the terminal symbols its
// rules end in (`Window1.wrl`, `Cornice2Chamfer.wrl`, …), which the thesis modelled in
// Cinema 4D, generated here in code. docs/assets.md lists them.
//
// Model frame: metres; x right along the facade, y up, z out of the wall: z = 0 is the wall
// plane, +z protrudes towards the street and negative z lies inside the wall (reveals,
// the dark rooms behind windows). x and y are centred on 0, since fitting maps a model's
// bounding box onto its scope centre to centre; z starts at the wall plane. Sizes are those
// of the real element (a window 1.2 × 2.0 m, a cornice profile 0.3 × 0.3 m); fitting
// stretches them, so what they carry is proportion. Triangles wind counter-clockwise seen
// from outside; every vertex has a normal and uvs in metres of the model.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/material.h"
#include "scene/mesh.h"

namespace veduta {

// Bilke's model types (table 2.2): how a model is fitted into its scope.
enum class ModelType {
    NoType,
    Wall,
    Door,
    Window,
    SmallRoof,
    Glass,
    Horizontal,
    HorizontalNoDepthScale,
    Vertical,
    VerticalNoDepthScale,
    Textured
};

// A surface of an asset takes one of the building's materials, chosen by category;
// MaterialCategory::None stands for the dark interior seen through windows.
struct Asset {
    std::string name;  // without ".wrl", e.g. "Window1"
    ModelType type = ModelType::NoType;
    Mesh mesh;                               // triangleMaterials hold indices into `surfaces`
    std::vector<MaterialCategory> surfaces;  // surfaces[0] is the one a rule's texture replaces
    Vec3f boundsMin, boundsMax;              // of mesh.positions
};

class AssetLibrary {
  public:
    // Generated on first use, then shared by every caller and thread.
    static const AssetLibrary &builtIn();

    // The asset a name means, with or without its ".wrl".
    std::optional<uint32_t> find(std::string_view name) const;
    // The asset a rule file's terminal symbol names: in Bilke's rules a terminal is a model's
    // name with ".wrl" (L418); without it the name is a rule's (the thesis has a rule
    // `Entrance1` that places the model `Entrance1.wrl`).
    std::optional<uint32_t> findTerminal(std::string_view symbol) const {
        return symbol.ends_with(".wrl") ? find(symbol) : std::nullopt;
    }
    bool isModelName(std::string_view symbol) const { return findTerminal(symbol).has_value(); }
    const Asset &operator[](uint32_t index) const { return assets_[index]; }
    size_t size() const { return assets_.size(); }

  private:
    AssetLibrary();

    std::vector<Asset> assets_;
    std::map<std::string, uint32_t, std::less<>> index_;  // name → index into assets_
};

}  // namespace veduta
