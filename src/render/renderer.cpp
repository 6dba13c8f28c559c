#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "film/adaptive_sampling.h"
#include "render/filter.h"
#include "render/sampling.h"

namespace veduta {

namespace {

std::vector<PixelWindow> makeTiles(const PixelWindow &window, int size) {
    std::vector<PixelWindow> tiles;
    for (int y = window.y0; y < window.y1; y += size) {
        for (int x = window.x0; x < window.x1; x += size) {
            tiles.push_back({x, y, std::min(x + size, window.x1), std::min(y + size, window.y1)});
        }
    }
    return tiles;
}

class FlushDenormals {
  public:
    FlushDenormals() : saved_(_mm_getcsr()) {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    }
    ~FlushDenormals() { _mm_setcsr(saved_); }
    FlushDenormals(const FlushDenormals &) = delete;
    FlushDenormals &operator=(const FlushDenormals &) = delete;

  private:
    unsigned saved_;
};

bool isFinite(const Vec3f &v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Samples of one pixel, with what every sample needs worked out once per render.
class PixelSampling {
  public:
    PixelSampling(const RenderScene &scene, const Bvh &bvh, uint32_t sampleOffset) :
        seed_(scene.settings.seed),
        sampleOffset_(sampleOffset),
        cameraRays_(scene.camera),
        depthOfField_(scene.camera.projection == Projection::Perspective && scene.camera.hasDepthOfField()),
        tracer_(scene, bvh),
        filter_(scene.settings.filter) {}

    // Takes the pixel's samples from the film's count up to `end` (numbers within the render).
    void run(Film &film, int x, int y, uint32_t end, RenderStats &local) const {
        size_t pixel = film.pixelIndex(x, y);
        uint32_t begin = film.sampleCount(pixel);
        // The data passes come from the pixel's sample 0, also in a render of a later range.
        if (begin == 0 && sampleOffset_ > 0) {
            PixelSampler sampler(seed_, uint32_t(x), uint32_t(y), 0);
            film.setFirstSample(pixel, tracer_.firstHit(cameraRay(x, y, sampler), local.rays));
        }
        PixelSeeds seeds(seed_, uint32_t(x), uint32_t(y));
        for (uint32_t s = begin; s < end; ++s) {
            uint32_t index = sampleOffset_ + s;
            PixelSampler sampler(seeds, index);
            FirstHit first;
            Vec3f L = tracer_.radiance(cameraRay(x, y, sampler), sampler, local.rays, &first);
            if (!isFinite(L)) {
                ++local.nonFiniteSamples;
                L = Vec3f(0.0f);
            }
            film.addSample(pixel, index, L, first);
            if (index == 0) film.setFirstSample(pixel, first);
        }
    }

  private:
    Ray cameraRay(int x, int y, PixelSampler &sampler) const {
        Vec2f offset = filter_.sample(sampler.next2D());
        // A pinhole draws no lens pair, so its samples keep their dimensions.
        Vec2f lens = depthOfField_ ? sampleConcentricDisk(sampler.next2D()) : Vec2f{};
        return cameraRays_.generate(float(x) + 0.5f + offset.x, float(y) + 0.5f + offset.y, lens);
    }

    uint32_t seed_, sampleOffset_;
    CameraRays cameraRays_;
    bool depthOfField_;
    PathTracer tracer_;
    FilterSampler filter_;
};

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

Film makeFilm(const RenderScene &scene, const RenderOptions &options) {
    const Camera &camera = scene.camera;
    PixelWindow whole{0, 0, camera.width, camera.height};
    PixelWindow window = options.region.empty() ? whole : options.region;
    if (!whole.contains(window)) {
        throw std::invalid_argument(fmt::format("the region {} {} {} {} is not inside the {}x{} image", window.x0,
                                                window.y0, window.x1, window.y1, camera.width, camera.height));
    }
    return Film(camera.width, camera.height, window);
}

void renderFilm(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options, Film &film,
                RenderStats &stats) {
    const Clock::time_point start = Clock::now();
    const double secondsBefore = stats.seconds;
    const RenderSettings &settings = scene.settings;
    const uint32_t total = settings.samplesPerPixel;
    const PixelSampling sampling(scene, bvh, options.sampleOffset);
    const std::vector<PixelWindow> tiles = makeTiles(film.window(), int(settings.tileSize));
    bool passesNeeded = options.timeLimitSeconds > 0 || options.afterPass;
    uint32_t step = options.passSamples ? options.passSamples : (passesNeeded ? kAdaptiveStep : total);
    Progress progress("render", film.pixelCount() * (total - std::min(stats.samplesDone, total)), "samples",
                      options.showProgress);

    while (stats.samplesDone < total) {
        const Clock::time_point passStart = Clock::now();
        const uint32_t done = stats.samplesDone, end = passEnd(done, total, step, settings);
        std::mutex statsMutex;
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, tiles.size(), 1),
            [&](const tbb::blocked_range<size_t> &r) {
                // Denormals only slow traversal down; Embree recommends flushing them. The thread's
                // own mode comes back when the task ends.
                FlushDenormals flushDenormals;
                RenderStats local;
                for (size_t t = r.begin(); t != r.end(); ++t) {
                    const PixelWindow &tile = tiles[t];
                    uint64_t taken = 0;
                    for (int y = tile.y0; y < tile.y1; ++y) {
                        for (int x = tile.x0; x < tile.x1; ++x) {
                            size_t pixel = film.pixelIndex(x, y);
                            if (!pixelNeedsSamples(film, pixel, done, total, settings)) continue;
                            taken += end - film.sampleCount(pixel);
                            sampling.run(film, x, y, end, local);
                        }
                    }
                    progress.advance(taken);
                }
                std::lock_guard lock(statsMutex);
                stats.rays += local.rays;
                stats.nonFiniteSamples += local.nonFiniteSamples;
            },
            tbb::simple_partitioner());
        stats.samplesDone = end;
        stats.seconds = secondsBefore + secondsSince(start);
        if (options.afterPass) options.afterPass(film, stats);
        double passSeconds = secondsSince(passStart);
        if (options.timeLimitSeconds > 0 && stats.seconds + passSeconds > options.timeLimitSeconds) break;
    }
    progress.finish();
    stats.seconds = secondsBefore + secondsSince(start);
}

Film render(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options, RenderStats *stats) {
    Film film = makeFilm(scene, options);
    RenderStats local;
    renderFilm(scene, bvh, options, film, local);
    if (stats) *stats = local;
    return film;
}

}  // namespace veduta
