// Where a point of a triangle lies on its textures and which way they run there: the (u, v) and
// the scale that texture lookups need for their footprint, and the tangent frame normal maps
// need. The path tracer (SurfaceLookup) and the preview work them out through this alike, so that
// both read the same texels.
#pragma once

#include <cstdint>

#include "scene/mesh.h"

namespace veduta {

struct TextureFrame {
    Vec2f uv;
    float uvPerMetre = 0;  // how fast (u, v) changes over the surface; 0 for a degenerate triangle
    Vec3f tangent;         // unit, world space, along +u; zero where unknown
    float bitangentSign = 1;
};

// A triangle as placed in the world: its edges p1 − p0 and p2 − p0 and cross(e1, e2), turned to
// the side the mesh faces where the placement mirrors.
struct WorldTriangle {
    Vec3f e1, e2, ng;
};

// At barycentric weights (w, u, v) of the triangle with vertex indices `idx` of a mesh with
// texture coordinates. `objectToWorld` places the mesh (null for a mesh in world space);
// `mirrored`: the placement turns windings around.
TextureFrame textureFrame(const Mesh &mesh, const uint32_t *idx, float w, float u, float v, const WorldTriangle &world,
                          const Transform *objectToWorld, bool mirrored);

}  // namespace veduta
