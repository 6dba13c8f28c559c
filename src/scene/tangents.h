// Per-vertex tangent frames for tangent-space normal maps.
#pragma once

#include "scene/mesh.h"

namespace veduta {

// Fills mesh.tangents and mesh.bitangentSigns, MikkTSpace-style: each triangle's dP/du and
// dP/dv, summed at its corners weighted by the corner angle, the tangent made orthogonal to
// the vertex normal, and the sign the handedness of (normal, tangent, dP/dv). Triangles whose
// uvs span no area contribute nothing; a vertex left without a tangent gets any unit vector
// orthogonal to its normal. A mesh without uvs or vertex normals gets no tangents (empty).
void computeTangents(Mesh &mesh);

}  // namespace veduta
