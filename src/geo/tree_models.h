// Procedural tree prototypes after Rilling 2006, ch. 7 (digest §4.5): a small bracketed, stochastic
// L-system rewritten a few times and read by a 3D turtle that draws tapered cylinders for
// trunk and branches and low-poly foliage blobs, bent by the thesis's tropism. Real geometry,
// not the thesis's crossed billboards: the path tracer instances one prototype per kind and
// variant many times. docs/vegetation.md describes the grammars and their parameters.
#pragma once

#include <cstdint>

#include "core/vecmath.h"
#include "geo/atkis.h"
#include "scene/mesh.h"
#include "scene/render_scene.h"

namespace veduta {

// The per-triangle materials a prototype is made with; the caller owns the ids.
struct TreeMaterials {
    MaterialId bark = 0;
    MaterialId foliage = 0;
};

inline constexpr uint32_t kTreeVariants = 3;         // per kind
inline constexpr size_t kTreeTriangleBudget = 8000;  // the most triangles any prototype has

// The angle in degrees by which the turtle's heading h turns towards the tropism vector t after
// each segment, as the thesis defines it: α_t = 90·(1 − 1/(1 + |h × t|)). The length of t is
// the strength of the effect; for unit vectors h ⟂ t gives 45° and h ∥ t gives 0°.
float tropismAngle(const Vec3f &heading, const Vec3f &tropism);
// `heading` (a unit vector) turned towards `tropism` by tropismAngle, but never past it.
Vec3f applyTropism(const Vec3f &heading, const Vec3f &tropism);

// One tree prototype: it stands on the origin, grows along +z and is exactly 1 high, so that an
// instance's scale is its height in metres. Bark triangles carry materials.bark, foliage
// triangles materials.foliage. Smooth vertex normals, uvs (bark: u round the stem, v along it
// in units of its circumference). The same arguments give the same mesh, bit for bit.
// `variant` picks one of kTreeVariants presets of a kind (taken modulo kTreeVariants); `seed`
// varies the stochastic rewriting and the angles within it. `kind` must not be Mixed
// (std::invalid_argument): placement decides between broadleaf and conifer.
Mesh treeModel(TreeKind kind, uint32_t variant, uint32_t seed, const TreeMaterials &materials);

// The materials `land/bark` and `land/foliage` (broadleaf) or `land/needles` (conifer): the
// scene's when it defines them, else built-in plain colours.
TreeMaterials treeMaterials(RenderSceneBuilder &builder, TreeKind kind);

}  // namespace veduta
