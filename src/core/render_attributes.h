// The EXR attributes a render writes about its samples and `veduta merge` reads back, and the
// render-time text both write. Here rather than in src/app so that src/film can use them.
#pragma once

#include <string>

namespace veduta {

inline constexpr const char *kSamplesAttribute = "veduta.samples";
inline constexpr const char *kSampleOffsetAttribute = "veduta.sampleOffset";
inline constexpr const char *kSeedAttribute = "veduta.seed";
inline constexpr const char *kSceneHashAttribute = "veduta.sceneHash";
inline constexpr const char *kRenderSecondsAttribute = "veduta.renderSeconds";

// Blender's stamp format for render times: "MM:SS.ss", or "HH:MM:SS.ss" from an hour on.
std::string blenderRenderTime(double seconds);

}  // namespace veduta
