// What a rendered EXR says about itself: the software, the samples and where they fall in the
// pixels' sequences, render time, seed, scene hash, camera (also as OpenEXR's standard
// worldToCamera), CRS and scene origin. docs/output.md lists the attributes; `veduta merge`
// reads some of them back.
#pragma once

#include <cstdint>

#include "core/layered_image.h"
#include "core/render_attributes.h"
#include "description/scene_description.h"
#include "render/renderer.h"

namespace veduta {

void addRenderMetadata(LayeredImage &image, const SceneDescription &description, const RenderScene &scene,
                       const RenderOptions &options, const RenderStats &stats, uint64_t sceneHash);

// OpenEXR's worldToCamera: row vectors (p' = p·M), the camera looking down its −z axis.
Matrix44 worldToCamera(const Camera &camera);

}  // namespace veduta
