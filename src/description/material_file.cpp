#include "description/material_file.h"

#include <array>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace veduta {

namespace {

constexpr std::array<std::pair<std::string_view, MaterialCategory>, 7> kCategories{{
    {"facade", MaterialCategory::Facade},
    {"roof", MaterialCategory::Roof},
    {"material", MaterialCategory::Material},
    {"door", MaterialCategory::Door},
    {"wall", MaterialCategory::Wall},
    {"window", MaterialCategory::Window},
    {"reflection", MaterialCategory::Reflection},
}};

MaterialCategory readCategory(const XmlElement &e) {
    if (!e.has("category")) return MaterialCategory::None;
    std::string name = e.string("category");
    for (const auto &[text, category] : kCategories) {
        if (name == text) return category;
    }
    e.failAt("category",
             fmt::format("unknown material category '{}' (facade, roof, material, door, wall, window, "
                         "reflection)",
                         name));
}

// `<kind>_map="file"` with an optional `<kind>_map_colorspace`. Colour maps default to the
// file's own colour space; data maps (normals, amounts) to "Non-Color", as in Blender.
ImageRef readMap(const XmlElement &e, const std::string &kind, bool colorData,
                 const std::filesystem::path &baseDirectory) {
    std::string attribute = kind + "_map", colorSpaceAttribute = kind + "_map_colorspace";
    ImageRef ref;
    if (!e.has(attribute.c_str())) {
        if (e.has(colorSpaceAttribute.c_str())) {
            e.failAt(colorSpaceAttribute.c_str(), fmt::format("'{}' without '{}'", colorSpaceAttribute, attribute));
        }
        return ref;
    }
    std::filesystem::path file = e.string(attribute.c_str());
    if (file.empty()) e.failAt(attribute.c_str(), fmt::format("attribute '{}' is empty", attribute));
    ref.file = file.is_absolute() ? file : baseDirectory / file;
    ref.loc = e.attributeLoc(attribute.c_str());
    ref.colorSpace = e.string(colorSpaceAttribute.c_str(), colorData ? "" : "Non-Color");
    return ref;
}

}  // namespace

MaterialDesc readMaterialElement(const XmlElement &e, const std::filesystem::path &baseDirectory) {
    MaterialDesc d;
    d.loc = e.loc();
    Material &m = d.material;
    m.name = e.string("name");
    m.category = readCategory(e);
    m.glass = e.boolean("glass", false);
    if (m.glass) {
        m.ior = e.number("ior", m.ior, 1.0f, 4.0f);
        m.glassTint = e.color("tint", m.glassTint, 0, 1);
    } else {
        d.diffuseMap = readMap(e, "diffuse", true, baseDirectory);
        d.specularMap = readMap(e, "specular", false, baseDirectory);
        d.normalMap = readMap(e, "normal", false, baseDirectory);
        d.reflectionMap = readMap(e, "reflection", false, baseDirectory);
        d.opacityMap = readMap(e, "opacity", false, baseDirectory);
        // Colours multiply their maps, so with a map they default to leaving it as it is.
        m.diffuse = e.color("diffuse", d.diffuseMap.given() ? Vec3f(1.0f) : m.diffuse, 0, 1);
        Vec3f specularColor = e.color("specular", Vec3f(1.0f, 1.0f, 0.85f), 0, 1);  // Bilke's base colour
        float intensity = e.number("specular_intensity", d.specularMap.given() ? 1.0f : 0.0f, 0, 1);
        m.specular = specularColor * intensity;
        m.shininess = e.number("shininess", m.shininess, 0, 1e5f);
        m.normalStrength = e.number("normal_strength", m.normalStrength, 0, 10);
        m.reflectivity = e.color("reflectivity", d.reflectionMap.given() ? Vec3f(1.0f) : m.reflectivity, 0, 1);
    }
    if (e.has("texture_size")) {
        std::vector<float> size = e.numbers("texture_size");
        if (size.size() == 1) size.push_back(size[0]);
        if (size.size() != 2 || size[0] <= 0 || size[1] <= 0) {
            e.failAt("texture_size", "texture_size takes one or two positive numbers (u and v extent)");
        }
        m.textureSize = {size[0], size[1]};
    }
    e.checkLeaf();
    return d;
}

std::vector<MaterialDesc> readMaterialFile(const std::filesystem::path &file) {
    XmlDocument doc = XmlDocument::fromFile(file);
    XmlElement root(doc, doc.root());
    if (root.name() != "materials") {
        root.fail(fmt::format("the root element is <{}>, expected <materials>", root.name()));
    }
    root.integer("version", 1, 1, 1);
    root.checkAllRead();
    std::vector<MaterialDesc> materials;
    for (const XmlElement &e : root.children()) {
        if (e.name() != "material") e.fail(fmt::format("<{}> cannot stand inside <materials>", e.name()));
        materials.push_back(readMaterialElement(e, file.parent_path()));
    }
    return materials;
}

}  // namespace veduta
