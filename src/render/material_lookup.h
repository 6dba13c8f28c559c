// From a material and a surface point to what the integrator needs: the BSDF with its maps
// looked up (through scene/material_maps.h, as the preview reads them) and its shading normal
// worked out, whether a cut-out removes the surface there, and what a shadow ray keeps when it
// passes.
#pragma once

#include "render/bsdf.h"
#include "render/surface_interaction.h"
#include "scene/material_maps.h"
#include "scene/render_scene.h"

namespace veduta {

class MaterialLookup {
  public:
    explicit MaterialLookup(const RenderScene &scene);

    // Whether any material lets rays pass (glass or cut-outs): only then must shadow rays
    // look at what they hit.
    bool anyPassThrough() const { return anyPassThrough_; }

    // `footprint` is the width, in metres, of the area a texture lookup should average.
    bool cutAway(const SurfaceInteraction &si, float footprint) const;
    // `wo` points from the surface back along the incoming ray.
    Bsdf bsdf(const SurfaceInteraction &si, const Vec3f &wo, float footprint) const;
    // What passes through the surface towards a distant light along `wi`: 0 for opaque ones.
    Vec3f transmittance(const SurfaceInteraction &si, const Vec3f &wi, float footprint) const;

  private:
    Vec3f shadingNormal(const Material &m, const SurfaceInteraction &si, const Vec3f &wo, float footprint) const;

    const RenderScene &scene_;
    MaterialMaps maps_;
    bool anyPassThrough_ = false;
};

}  // namespace veduta
