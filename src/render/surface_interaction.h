// What the integrator needs to know about the point a ray hit, in world space.
#pragma once

#include <vector>

#include "render/bvh.h"
#include "scene/render_scene.h"

namespace veduta {

struct SurfaceInteraction {
    Vec3f position;
    Vec3f geometricNormal;  // unit, facing the side the ray came from
    Vec3f shadingNormal;    // unit, on the same side as geometricNormal
    MaterialId material = 0;
};

class SurfaceLookup {
  public:
    explicit SurfaceLookup(const RenderScene &scene);
    SurfaceInteraction at(const Hit &hit, const Vec3f &rayDirection) const;

  private:
    const RenderScene &scene_;
    std::vector<Transform> instanceNormalTransforms_;
};

// A ray origin just off the surface on the side `normal` points to, so that the new ray does
// not hit the surface it starts from (Wächter and Binder, Ray Tracing Gems, ch. 6): offsets of
// a few ulps that grow with the coordinates' magnitude, not a fixed epsilon.
Vec3f offsetRayOrigin(const Vec3f &position, const Vec3f &normal);

}  // namespace veduta
