// Wavefront OBJ of a RenderScene with its materials in an MTL, written by veduta itself into
// one text buffer. Z up, veduta's own frame; OBJ has no instancing, so every instance is
// written as a transformed copy. Each baked mesh and each copy is an object (`o`) named as the
// render's objects are, with a `usemtl` per material; the MTL has Phong colours (Kd, Ks, Ns),
// the PBR extension Blender reads (Pr, Pm), glass as a transmission filter, and the maps as
// image files copied beside it.
#pragma once

#include <filesystem>

#include "io/export_job.h"
#include "scene/render_scene.h"

namespace veduta {

class Progress;

// OUT.obj, OUT.mtl, the map images and the georeference sidecars. Throws std::runtime_error
// (or InputError for a map file that has gone) when an image cannot be read.
ExportResult writeObj(const RenderScene &scene, const std::filesystem::path &out, const ExportOptions &options,
                      Progress &progress);

}  // namespace veduta
