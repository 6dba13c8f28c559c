// PLY (binary little-endian) of a RenderScene for point-cloud and mesh tools (MeshLab,
// CloudCompare, Blender): one mesh, Z up in veduta's frame, every instance written as a
// transformed copy. Vertices carry x y z, nx ny nz, s t when any mesh has texture coordinates
// (0 where one has none), and red green blue: the material's diffuse colour in sRGB, since
// Blender and MeshLab read colours per vertex and Blender ignores per-face properties. Faces
// carry their vertex indices and material_index, an index into the materials the header names
// in comments ("comment material 3 brick").
#pragma once

#include <filesystem>

#include "io/export_job.h"
#include "scene/render_scene.h"

namespace veduta {

class Progress;

// OUT.ply and the georeference sidecars.
ExportResult writePly(const RenderScene &scene, const std::filesystem::path &out, const ExportOptions &options,
                      Progress &progress);

}  // namespace veduta
