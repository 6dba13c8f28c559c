// Shading normals from tangent-space normal maps, and the correction that keeps them from
// producing black edges: a shading normal tilted away from the viewer can mirror wo below the
// geometric surface, where no light may come from.
#pragma once

#include "core/vecmath.h"

namespace veduta {

// The world-space shading normal a tangent-space normal-map texel gives (MikkTSpace
// convention, OpenGL green = +bitangent): texel 2·rgb − 1 in the frame (tangent, bitangent,
// n), with the tangent orthogonalised against n and bitangent = sign · cross(n, tangent).
// `strength` blends from n (0) to the mapped normal (1) and beyond, as Cycles' Normal Map node:
// normalize(n + strength · (mapped − n)). Unit n; tangent any length, not parallel to n.
Vec3f normalFromMap(Vec3f texel, const Vec3f &n, const Vec3f &tangent, float bitangentSign, float strength);

// Cycles' ensure_valid_reflection (v3.4, kernel/closure/bsdf_util.h): when the mirror image of
// wo about n lies less than t = min(0.9 · (wo·ng), 0.01) above the geometric surface, n is
// turned in the plane of (ng, n) towards ng just far enough that the mirror image lies at t.
// Otherwise n is returned unchanged. ng and wo on the same side, all unit vectors. Unlike
// Cycles it always takes the root that puts the mirror image at t (see the .cpp).
Vec3f ensureValidReflection(const Vec3f &ng, const Vec3f &wo, const Vec3f &n);

}  // namespace veduta
