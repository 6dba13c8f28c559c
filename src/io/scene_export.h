// Writing a RenderScene's geometry and materials for other tools (Blender, CityEngine, QGIS 3D,
// three.js) as Wavefront OBJ or glTF 2.0. docs/export.md says what each format keeps.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>

#include "scene/render_scene.h"

namespace veduta {

enum class ExportFormat { Obj, Gltf, Glb };

// The format a file name asks for by its extension (.obj, .gltf, .glb; any case), or none.
std::optional<ExportFormat> exportFormatForPath(const std::filesystem::path &path);

struct ExportStats {
    size_t meshes = 0;     // meshes in the file: baked meshes and prototypes (OBJ: every copy)
    size_t instances = 0;  // prototype placements (OBJ: written out as copies)
    size_t triangles = 0;  // as drawn, every instance counted
    size_t files = 0;      // files written: the main file and its .mtl or .bin
};

// Writes the scene's geometry and materials to `out` and the side files beside it.
// glTF (.gltf with a .bin, or one .glb) keeps instancing: one mesh per prototype (and material
// override), one node per instance with its matrix, a node per baked mesh; it is Y up, so
// everything goes through zUpToYUp. OBJ has no instancing: instances are written as transformed
// copies, in veduta's own Z-up frame, with the materials in an .mtl beside it.
// Every file is written atomically. Throws std::runtime_error when Assimp cannot encode the
// scene or a file cannot be written.
ExportStats exportScene(const RenderScene &scene, const std::filesystem::path &out, ExportFormat format);

}  // namespace veduta
