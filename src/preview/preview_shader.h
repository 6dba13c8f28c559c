// How the preview colours the surface a pixel shows in the modes that shade it (shaded, albedo,
// normal, thesis), and what the background shows. Maps are read through scene/material_maps.h
// with the path tracer's footprint, lobes are weighed as its BSDF weighs them
// (scene/lobe_weights.h), so that the albedo mode is its albedo pass and the shaded mode its
// direct sunlight, with the sky's mean radiance for the light from everywhere else.
#pragma once

#include <algorithm>
#include <vector>

#include "preview/preview.h"
#include "preview/thesis_shading.h"
#include "scene/lobe_weights.h"
#include "scene/material_maps.h"

namespace veduta {

// What the preview knows of the surface at a pixel, in world space.
struct PreviewSurface {
    Vec3f position;
    Vec3f normal;           // interpolated shading normal, unit, on the side the camera sees
    Vec3f geometricNormal;  // unit, on the side the camera sees
    Vec3f toEye;            // unit, from the surface towards the eye
    MaterialId material = 0;
    bool backFacing = false;  // the camera sees the side the mesh's winding faces away from
    TexturePoint map;         // where the material's maps are read
    Vec3f tangent;            // along +u, unit; zero where unknown (no normal map then)
    float bitangentSign = 1;
};

class PreviewShader {
  public:
    PreviewShader(const RenderScene &scene, PreviewMode mode);

    bool hasMaps(MaterialId m) const { return materials_[m].hasMaps; }
    bool cutsOut(MaterialId m) const { return scene_.materials[m].opacityMap != kNoTexture; }
    // Whether the colour in this mode follows from the material and the interpolated normal
    // alone: a material without maps or view-dependent lobes, in the shaded or albedo mode, or in
    // the normal mode on a flat triangle (whose normal needs no correction). Its point's position,
    // eye direction and maps need not be worked out then, and a flat triangle has one colour. The
    // shaded mode takes such a material's smooth normals as interpolated, without the path
    // tracer's correction against black edges: that changes the light on few pixels, at grazing
    // angles, and working out the surface point for it at every pixel made the benchmark's
    // default scene 1.6 times slower.
    bool fromNormalAlone(MaterialId m, bool smoothNormals) const {
        return materials_[m].uniform && mode_ != PreviewMode::Thesis &&
            !(mode_ == PreviewMode::Normal && smoothNormals);
    }
    // That colour, for `normal` on the side the camera sees; `sunVisible` false in a shadow.
    Vec3f colorFromNormal(MaterialId m, const Vec3f &normal, bool sunVisible = true) const {
        const MaterialShading &shading = materials_[m];
        if (mode_ == PreviewMode::Albedo) return shading.albedo;
        if (mode_ == PreviewMode::Normal) return normal * 0.5f + Vec3f(0.5f);
        float cosine = sunVisible ? std::max(0.0f, dot(normal, sunDirection_)) : 0.0f;
        return shading.sunTerm * cosine + shading.skyTerm;
    }

    // A cut-out's verdict at the point, as the path tracer's.
    bool cutAway(const PreviewSurface &s) const;
    // The colour in the shaded, albedo, normal or thesis mode; `sunVisible` false in a shadow.
    Vec3f color(const PreviewSurface &s, bool sunVisible) const;
    // The shaded and thesis modes show the environment behind everything, the others black.
    bool constantBackground() const { return !scene_.environment.cubemap || !showsEnvironment(); }
    Vec3f background(const Vec3f &direction) const;

  private:
    struct MaterialShading {
        bool hasMaps = false;
        bool uniform = false;
        LobeWeights plain;  // the weights of a material without maps
        // A uniform material's albedo (black for glass, as the albedo pass) and its shaded colour,
        // sunTerm · cos θ + skyTerm.
        Vec3f albedo, sunTerm, skyTerm;
    };

    bool showsEnvironment() const { return mode_ == PreviewMode::Shaded || mode_ == PreviewMode::Thesis; }
    // The shading normal with the material's normal map, as the path tracer's before its
    // correction against black edges.
    Vec3f mappedNormal(const PreviewSurface &s, const Material &m) const;
    // The shading normal the path tracer's BSDF and normal pass take: normal-mapped and
    // corrected against black edges; glass shades with its geometric normal.
    Vec3f shadingNormal(const PreviewSurface &s, const Material &m) const;
    Vec3f shaded(const PreviewSurface &s, const Material &m, const LobeWeights &w, bool sunVisible) const;
    Vec3f thesis(const PreviewSurface &s, const Material &m, const Vec3f &base) const;

    const RenderScene &scene_;
    PreviewMode mode_;
    MaterialMaps maps_;
    std::vector<MaterialShading> materials_;
    Vec3f skyRadiance_;  // the environment's mean radiance: the light from everywhere but the sun
    Vec3f sunDirection_;
    ThesisLight thesisLight_;
};

}  // namespace veduta
