// Rendering an image, or a window of it, into a film: tiles spread over TBB's threads, each
// pixel's samples summed in a fixed order, so that the film is bit-identical for any thread
// count, tile size or region. The samples come in passes; between passes the film is whole,
// which is where checkpoints are written, adaptive sampling decides and time limits stop.
#pragma once

#include <functional>

#include "core/layered_image.h"
#include "film/film.h"
#include "film/render_stats.h"
#include "render/bvh.h"
#include "render/path_tracer.h"

namespace veduta {

struct RenderOptions {
    bool showProgress = false;
    PixelWindow region;           // empty: the whole image
    uint32_t sampleOffset = 0;    // pixels take samples [sampleOffset, sampleOffset + spp) of their sequence
    double timeLimitSeconds = 0;  // 0: none; otherwise no pass starts that would end after it
    // Samples per pass without adaptive sampling; 0: all in one pass, unless a time limit or
    // afterPass needs several. Changes speed only, never the image.
    uint32_t passSamples = 0;
    // Called after each pass with the whole film, e.g. to write a checkpoint.
    std::function<void(Film &, const RenderStats &)> afterPass;
};

// The film a render of `options.region` (or the whole image) starts from.
Film makeFilm(const RenderScene &scene, const RenderOptions &options);

// Renders into `film` from where `stats` says it stands (nothing done for a fresh film, or
// what a checkpoint recorded) until every pixel has its samples, has converged, or the time
// limit is reached. The scene's settings give the samples per pixel and the tile size.
void renderFilm(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options, Film &film, RenderStats &stats);

// A whole fresh render.
Film render(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options = {}, RenderStats *stats = nullptr);

}  // namespace veduta
