// Writing a RenderScene's geometry and materials for other tools (Blender, CityEngine, QGIS 3D,
// three.js, MeshLab) as glTF 2.0, Wavefront OBJ or PLY. docs/export.md says what each format
// keeps; the encoders are gltf_writer.h, obj_writer.h and ply_writer.h.
#pragma once

#include <filesystem>
#include <optional>

#include "io/export_job.h"
#include "scene/render_scene.h"

namespace veduta {

enum class ExportFormat { Obj, Gltf, Glb, Ply };

// The format a file name asks for by its extension (.obj, .gltf, .glb, .ply; any case), or none.
std::optional<ExportFormat> exportFormatForPath(const std::filesystem::path &path);

// Writes the scene to `out` and its side files beside it (.bin, .mtl, images, the georeference
// sidecars .prj and .geo.json). All files are encoded in memory first and then written
// atomically as one set: either all of them change or none (core/atomic_file.h). Throws
// std::runtime_error when a file cannot be written or something not a file stands where one
// goes, InputError when a map's image file cannot be read.
ExportStats exportScene(const RenderScene &scene, const std::filesystem::path &out, ExportFormat format,
                        const ExportOptions &options = {});

}  // namespace veduta
