// What a rendered EXR says about itself: the software, the samples and where they fall in the
// pixels' sequences, render time, seed, scene file and hash, camera (also as OpenEXR's standard
// worldToCamera and worldToNDC, which Nuke reads), CRS and scene origin. docs/output.md lists the attributes; `veduta
// merge` reads some of them back.
#pragma once

#include <cstdint>
#include <string>

#include "core/layered_image.h"
#include "core/render_attributes.h"
#include "description/scene_description.h"
#include "render/renderer.h"

namespace veduta {

// `sceneFile` as the command line gave it ("" for the built-in default scene).
void addRenderMetadata(LayeredImage &image, const std::string &sceneFile, const SceneDescription &description,
                       const RenderScene &scene, const RenderOptions &options, const RenderStats &stats,
                       uint64_t sceneHash);

// OpenEXR's worldToCamera: row vectors (p' = p·M), the camera looking down its −z axis.
Matrix44 worldToCamera(const Camera &camera);
// OpenEXR's worldToNDC: row vectors, then divided by w; (0, 0) is the display window's top-left
// corner, (1, 1) its bottom-right one, lens shift included.
Matrix44 worldToNdc(const Camera &camera);

}  // namespace veduta
