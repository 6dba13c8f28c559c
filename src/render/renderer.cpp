#include "render/renderer.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "render/filter.h"

namespace veduta {

namespace {

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += size) {
        for (int x = 0; x < width; x += size) tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
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

}  // namespace

RgbaImage render(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options, RenderStats *stats) {
    auto start = std::chrono::steady_clock::now();
    const Camera &camera = scene.camera;
    const CameraRays cameraRays(camera);
    const RenderSettings &settings = scene.settings;
    RgbaImage film(camera.width, camera.height);
    PathTracer tracer(scene, bvh);
    const FilterSampler filter(settings.filter);
    std::vector<Tile> tiles = makeTiles(camera.width, camera.height, int(settings.tileSize));
    Progress progress("render", tiles.size(), "tiles", options.showProgress);

    std::mutex statsMutex;
    RenderStats total;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t> &range) {
        // Denormals only slow traversal down; Embree recommends flushing them. The thread's
        // own mode comes back when the task ends.
        FlushDenormals flushDenormals;
        RenderStats local;
        for (size_t t = range.begin(); t != range.end(); ++t) {
            const Tile &tile = tiles[t];
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    double sum[3] = {0, 0, 0};
                    for (uint32_t s = 0; s < settings.samplesPerPixel; ++s) {
                        PixelSampler sampler(settings.seed, uint32_t(x), uint32_t(y), s);
                        Vec2f offset = filter.sample(sampler.next2D());
                        Ray ray = cameraRays.generate(float(x) + 0.5f + offset.x, float(y) + 0.5f + offset.y);
                        Vec3f L = tracer.radiance(ray, sampler, local.rays);
                        if (!isFinite(L)) {
                            ++local.nonFiniteSamples;
                            continue;
                        }
                        sum[0] += L.x;
                        sum[1] += L.y;
                        sum[2] += L.z;
                    }
                    double inv = 1.0 / settings.samplesPerPixel;
                    film.set(x, y, {float(sum[0] * inv), float(sum[1] * inv), float(sum[2] * inv)});
                }
            }
            progress.advance();
        }
        std::lock_guard lock(statsMutex);
        total.rays += local.rays;
        total.nonFiniteSamples += local.nonFiniteSamples;
    }, tbb::simple_partitioner());
    progress.finish();

    total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = total;
    return film;
}

}  // namespace veduta
