// What a rendered EXR says about itself: the software, the samples and where they fall in the
// pixels' sequences, render time, seed, scene hash, camera (also as OpenEXR's standard
// worldToCamera), CRS and scene origin. docs/output.md lists the attributes; `veduta merge`
// reads some of them back.
#pragma once

#include <cstdint>

#include "core/layered_image.h"
#include "render/renderer.h"
#include "scene/scene_description.h"

namespace veduta {

// Attribute names `veduta merge` relies on.
inline constexpr const char *kSamplesAttribute = "veduta.samples";
inline constexpr const char *kSampleOffsetAttribute = "veduta.sampleOffset";
inline constexpr const char *kSeedAttribute = "veduta.seed";
inline constexpr const char *kSceneHashAttribute = "veduta.sceneHash";
inline constexpr const char *kRenderSecondsAttribute = "veduta.renderSeconds";

void addRenderMetadata(LayeredImage &image, const SceneDescription &description, const RenderScene &scene,
                       const RenderOptions &options, const RenderStats &stats, uint64_t sceneHash);

// Blender's stamp format for render times: "MM:SS.ss", or "HH:MM:SS.ss" from an hour on.
std::string blenderRenderTime(double seconds);

// OpenEXR's worldToCamera: row vectors (p' = p·M), the camera looking down its −z axis.
Matrix44 worldToCamera(const Camera &camera);

}  // namespace veduta
