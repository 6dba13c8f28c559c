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
    float distance = 0;  // along the ray that found it

    // For textures; all zero when the mesh has no texture coordinates or the material no maps.
    Vec2f uv;
    float uvPerMetre = 0;  // how fast (u, v) changes over the surface, for texture footprints
    // For normal maps: the tangent along +u (unit, world space) and the sign that makes the
    // bitangent sign · cross(n, tangent), n being the side the mesh faces, not the ray.
    Vec3f tangent;
    float bitangentSign = 1;
    bool backFacing = false;  // the ray came from the side the mesh's winding faces away from

    // Whose surface it is (RenderScene's BakedMesh or Instance), for the id passes.
    ObjectId objectId = 0;
    uint32_t buildingId = 0;
    uint32_t instanceId = 0;
};

class SurfaceLookup {
  public:
    explicit SurfaceLookup(const RenderScene &scene);
    SurfaceInteraction at(const Hit &hit, const Vec3f &rayDirection) const;

  private:
    const RenderScene &scene_;
    std::vector<Transform> instanceNormalTransforms_;
    std::vector<char> instanceMirrors_;  // the placement turns windings around
    std::vector<char> materialHasMaps_;  // else texture coordinates and tangents are not worked out
};

// A ray origin just off the surface on the side `normal` points to, so that the new ray does
// not hit the surface it starts from (Wächter and Binder, Ray Tracing Gems, ch. 6): offsets of
// a few ulps that grow with the coordinates' magnitude, not a fixed epsilon.
Vec3f offsetRayOrigin(const Vec3f &position, const Vec3f &normal);

}  // namespace veduta
