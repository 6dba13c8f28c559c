// Whether a mesh closes the solids it bounds: the checks of the futuristic city's prisms,
// slabs and crossings (digest-002 §10.2, "meshes are watertight").
#pragma once

#include "scene/mesh.h"

namespace veduta {

// Every edge, its ends merged by position to 0.1 mm, is walked by as many triangles one way as
// the other: the surface has no hole, no crack and no face turned against its neighbours. A
// union of closed solids passes too.
bool isWatertight(const Mesh &mesh);

// The volume the triangles enclose (the divergence theorem): positive when they face out.
double enclosedVolume(const Mesh &mesh);

}  // namespace veduta
