// A triangle mesh as generators emit it and renderers consume it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

using MaterialId = uint32_t;
inline constexpr MaterialId kNoMaterial = ~0u;

struct Mesh {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;  // per vertex; empty means flat shading
    std::vector<Vec2f> uvs;      // per vertex; may be empty
    // Per vertex, for normal maps (MikkTSpace-style): the tangent follows +u, and the
    // bitangent is sign · cross(normal, tangent). Empty until computeTangents (tangents.h).
    std::vector<Vec3f> tangents;
    std::vector<float> bitangentSigns;
    std::vector<uint32_t> indices;              // three per triangle
    std::vector<MaterialId> triangleMaterials;  // one per triangle

    size_t triangleCount() const { return indices.size() / 3; }
    size_t vertexCount() const { return positions.size(); }

    // Appends `other` with `transform` applied, keeping its per-triangle materials. Clears the
    // tangents: compute them once the mesh is complete.
    void append(const Mesh &other, const Transform &transform);
    // Gives every triangle the same material.
    void setMaterial(MaterialId material);
};

// `mesh` with the vertices that agree in position (to 0.1 mm), normal and texture coordinates
// merged, so that pieces laid edge to edge share their corners; the first of each group is
// kept and the order of first appearance too. Without tangents (computeTangents on the
// result); its storage has no spare room.
Mesh weldVertices(const Mesh &mesh);

}  // namespace veduta
