// glTF 2.0 of a RenderScene, written by veduta itself on the specification rather than
// through a library: every buffer is filled straight from the scene's meshes and the JSON is
// printed into one string (docs/export.md gives the reasons and the timings).
//
// Y up: positions, normals, tangents and matrices go through zUpToYUp. Instancing is kept: one
// mesh per prototype (and material override), one node per instance with its matrix, a node
// per baked mesh; each mesh has a primitive per material. One bufferView per attribute kind
// (positions, normals, texture coordinates, tangents, 16- and 32-bit indices), accessors at
// offsets in them. Materials are metallic-roughness, glass through KHR_materials_transmission
// and KHR_materials_ior; PNG and JPEG maps become textures; the camera a camera node; the sun
// a KHR_lights_punctual directional light; the georeference the asset's extras.
#pragma once

#include <filesystem>

#include "io/export_job.h"
#include "scene/render_scene.h"

namespace veduta {

class Progress;

// The files of `out`: OUT.gltf with OUT.bin and the image files beside it, or one OUT.glb
// (`binary`) with the images inside, and the georeference sidecars. Throws
// std::runtime_error when an image file cannot be read.
ExportResult writeGltf(const RenderScene &scene, const std::filesystem::path &out, bool binary,
                       const ExportOptions &options, Progress &progress);

}  // namespace veduta
