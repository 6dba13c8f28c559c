// Surface materials: the Phong model of Bilke's material table (diffuse, specular,
// shininess; normal, specular and reflection maps) made physically plausible, plus thin
// glass for window panes and opacity cut-outs for foliage. docs/materials.md documents the
// fields; render/bsdf.h turns them into a BSDF at each hit.
#pragma once

#include <string>
#include <utility>

#include "core/vecmath.h"
#include "scene/textures.h"

namespace veduta {

// The categories of Bilke's table 2.4. They say what a material is for (which generated
// part may pick it); rendering does not depend on them.
enum class MaterialCategory { None, Facade, Roof, Material, Door, Wall, Window, Reflection };

struct Material {
    std::string name;
    MaterialCategory category = MaterialCategory::None;

    Vec3f diffuse{0.8f};  // k_d, linear Rec.709; multiplies the diffuse map
    TextureId diffuseMap = kNoTexture;
    Vec3f specular{0.0f};  // k_s: specular colour × intensity; multiplied by the specular map
    TextureId specularMap = kNoTexture;
    float shininess = 32;              // Phong exponent n
    TextureId normalMap = kNoTexture;  // tangent space, OpenGL convention (green = +v)
    float normalStrength = 1;
    Vec3f reflectivity{0.0f};  // a mirror lobe (PVSUR); multiplied by the reflection map
    TextureId reflectionMap = kNoTexture;
    TextureId opacityMap = kNoTexture;  // cut-out: below 0.5 the surface is not there

    bool glass = false;  // a thin dielectric pane; the fields above are then unused
    float ior = 1.5f;
    Vec3f glassTint{1.0f};

    // Texture coordinates are divided by this: a texture spans `textureSize` units of u and
    // v, metres on the built-in shapes.
    Vec2f textureSize{1.0f, 1.0f};

    bool hasMaps() const {
        return diffuseMap != kNoTexture || specularMap != kNoTexture || normalMap != kNoTexture ||
            reflectionMap != kNoTexture || opacityMap != kNoTexture;
    }
    // Whether light may pass the surface: shadow rays weigh such surfaces rather than stop.
    bool passesLight() const { return glass || opacityMap != kNoTexture; }

    // A plain Lambertian material, as generators and tests make them.
    static Material lambertian(std::string name, const Vec3f &albedo) {
        Material m;
        m.name = std::move(name);
        m.diffuse = albedo;
        return m;
    }
};

}  // namespace veduta
