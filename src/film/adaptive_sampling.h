// Adaptive sampling with Cycles' half buffers: every pixel keeps the sum of its even-numbered
// samples beside the sum of all, so the difference of the even and odd halves estimates the
// variance of each sample, v, relative as relMSE weighs it (pbrt's, Mitsuba's and `veduta
// diff`'s measure). A pixel stops once √v / n, with n its samples, falls below the noise
// threshold: its next sample would lower its relMSE v / n by about v / n², less than the
// threshold squared. Where every pixel stops at the same gain per sample, each has samples in
// proportion to √v, which makes the image's relMSE least for its total samples. Cycles' own
// estimate (the halves' difference over the square root of the brightness) stops at equal
// noise instead; on the default scene it saves less (docs/output.md, "Adaptive sampling").
//
// Unlike Cycles, a pixel's decision does not look at its neighbours: a render of a region then
// samples each pixel exactly as the full render does, so regions stay bit-identical.
#pragma once

#include <cstdint>

#include "core/rel_mse.h"
#include "film/film.h"
#include "scene/render_settings.h"

namespace veduta {

// Checks follow the first `adaptiveMinSamples` samples every this many samples.
inline constexpr uint32_t kAdaptiveStep = 4;

// The pixel's noise estimate √v / n, in the units of the threshold; infinite before both
// halves have a sample.
float pixelNoise(const Film &film, size_t pixel);

// Samples every pixel takes before its first check: settings.minSamples, or when that is 0
// (automatic) max(16, samples / 16), never more than the samples asked for.
uint32_t adaptiveMinSamples(const RenderSettings &settings);

// Whether a pixel that has taken `done` samples of `total` takes more: it has not yet taken
// them all, and (with adaptive sampling) it has taken fewer than the minimum, or its last
// check came after exactly `done` samples and found it still noisy. A pure function of the
// film, so a resumed render makes the same decisions.
bool pixelNeedsSamples(const Film &film, size_t pixel, uint32_t done, uint32_t total, const RenderSettings &settings);

// Where the render pass starting after `done` samples ends. With adaptive sampling the passes
// are fixed (the minimum, then kAdaptiveStep at a time) because decisions fall at their ends;
// otherwise a pass is `step` samples, which changes nothing in the image.
uint32_t passEnd(uint32_t done, uint32_t total, uint32_t step, const RenderSettings &settings);

}  // namespace veduta
