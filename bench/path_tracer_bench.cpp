// Path-tracer throughput against Embree's own: rays per second of a whole render, and raw
// rtcIntersect1 throughput for incoherent rays in the same BVH, in the same run, on one
// thread each. Two scenes: /0 the built-in default scene (a few thousand triangles, where
// traversal is cheap and shading weighs most), /1 scenes/bench/instances-10k.xml (10^8
// effective triangles). Prints the medians and their ratio per scene.
//
//   build/release/bench/bench_path_tracer [--benchmark_repetitions=5]
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <tbb/task_arena.h>
#include <xmmintrin.h>

#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "median_reporter.h"
#include "render/embree_util.h"
#include "render/renderer.h"
#include "render/sampling.h"
#include "render/surface_interaction.h"

namespace veduta {
namespace {

struct BenchScene {
    RenderScene scene;
    Bvh bvh;
    std::vector<Ray> incoherentRays;

    explicit BenchScene(const std::string &path) :
        scene(makeScene(path)), bvh(scene), incoherentRays(makeIncoherentRays()) {}

    static RenderScene makeScene(const std::string &path) {
        SceneDescription d = loadSceneDescription(path);
        d.camera.width = 160;
        d.camera.height = 90;
        d.settings.samplesPerPixel = 16;
        return buildRenderScene(d);
    }

    // Rays leaving visible surface points in uniformly random directions: what diffuse
    // bounces look like to the BVH, without any coherence between neighbours.
    std::vector<Ray> makeIncoherentRays() const {
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> u(0, 1);
        SurfaceLookup surfaces(scene);
        CameraRays cameraRays(scene.camera);
        std::vector<Ray> rays;
        while (rays.size() < 1u << 20) {
            Ray primary = cameraRays.generate(u(rng) * float(scene.camera.width), u(rng) * float(scene.camera.height));
            std::optional<Hit> hit = bvh.intersect(primary, false);
            if (!hit) continue;
            SurfaceInteraction si = surfaces.at(*hit, primary.direction);
            Vec3f local = sampleCosineHemisphere({u(rng), u(rng)});
            rays.push_back({offsetRayOrigin(si.position, si.geometricNormal),
                            Frame::fromNormal(si.geometricNormal).toWorld(local)});
        }
        std::shuffle(rays.begin(), rays.end(), rng);
        return rays;
    }
};

const std::string kScenes[] = {"", VEDUTA_SOURCE_DIR "/scenes/bench/instances-10k.xml"};

BenchScene &benchScene(int64_t index) {
    static std::map<int64_t, std::unique_ptr<BenchScene>> scenes;
    std::unique_ptr<BenchScene> &s = scenes[index];
    if (!s) s = std::make_unique<BenchScene>(kScenes[index]);
    return *s;
}

void BM_PathTracerRays(benchmark::State &state) {
    BenchScene &b = benchScene(state.range(0));
    tbb::task_arena one(1);
    RayCounts rays;
    for (auto _ : state) {
        RenderStats stats;
        one.execute([&] { benchmark::DoNotOptimize(render(b.scene, b.bvh, RenderOptions{}, &stats)); });
        rays += stats.rays;
    }
    // Every ray the render traces counts: coherent camera rays, incoherent bounce rays and
    // shadow rays (rtcOccluded1), as Embree's tutorials and pbrt count them.
    state.counters["rays_per_second"] = benchmark::Counter(double(rays.total()), benchmark::Counter::kIsRate);
    state.counters["camera_share"] = double(rays.camera) / double(rays.total());
    state.counters["bounce_share"] = double(rays.bounce) / double(rays.total());
    state.counters["shadow_share"] = double(rays.shadow) / double(rays.total());
}

void BM_EmbreeIncoherentIntersect1(benchmark::State &state) {
    BenchScene &b = benchScene(state.range(0));
    auto *scene = static_cast<RTCScene>(b.bvh.embreeScene());
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    uint64_t rays = 0, hits = 0;
    for (auto _ : state) {
        for (const Ray &ray : b.incoherentRays) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
            RTCRayHit rh = toRayHit(ray, std::numeric_limits<float>::infinity());
            rtcIntersect1(scene, &context, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
        rays += b.incoherentRays.size();
    }
    benchmark::DoNotOptimize(hits);
    state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_PathTracerRays)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_EmbreeIncoherentIntersect1)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    return veduta::benchmarkMain(argc, argv, [](const veduta::MedianReporter &reporter) {
        using namespace veduta;
        for (const std::string scene : {"0", "1"}) {
            const auto *traced = reporter.find("BM_PathTracerRays/" + scene);
            const auto *raw = reporter.find("BM_EmbreeIncoherentIntersect1/" + scene);
            if (!traced || !raw) continue;
            double pt = traced->counters.at("rays_per_second"), embree = raw->counters.at("rays_per_second");
            std::printf(
                "\nscene %s: path tracer %.3f Mrays/s, raw Embree incoherent rtcIntersect1 %.3f Mrays/s, ratio %.1f %%",
                scene.c_str(), pt * 1e-6, embree * 1e-6, 100.0 * pt / embree);
        }
        std::printf("\n");
    });
}
