// The preview rasterizer against Mesa's llvmpipe (through OSMesa) drawing the same triangles,
// at the same resolution, with the same shading (the preview's Shaded mode, which draws these
// scenes' plain Lambertian materials under a constant sky as Lambert sun, no shadows, sky
// irradiance, two-sided), in the same run, both on two threads. Frame times are
// wall-clock: both renderers work on several threads. Scenes:
//   default        the built-in default scene at 1280x720 (a few thousand triangles)
//   spheres-10M    1,000 instances of a 10,000-triangle sphere on a grid, 1920x1080
//   instances-10k  scenes/bench/instances-10k.xml at 1920x1080 (10^8 effective triangles)
// Prints per scene the median frame times, their ratio, and how many pixels differ by more than
// 8/255 in 8-bit sRGB, so that one can see that both drew the same picture.
//
//   build/release/bench/bench_preview [--benchmark_repetitions=5] [--benchmark_filter=default]
//                                     [--images=DIR]   (writes both images and their difference)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "io/output_files.h"
#include "median_reporter.h"
#include "osmesa_renderer.h"
#include "preview/preview.h"
#include "scene/shapes.h"

namespace veduta {
namespace {

// Threads for each renderer: a TBB arena for the preview, LP_NUM_THREADS for llvmpipe's
// rasterizer threads. (llvmpipe runs vertex processing on the calling thread besides.)
constexpr int kThreads = 2;

RenderScene fileScene(const std::string &path, int width, int height) {
    SceneDescription d = loadSceneDescription(path);
    d.camera.width = width;
    d.camera.height = height;
    return buildRenderScene(d);
}

// 10^7 effective triangles, far fewer than instances-10k, so that llvmpipe's single-threaded
// vertex processing still gives frame times one can repeat. Three of four instances override
// the material, so that path is drawn (and compared) too.
RenderScene sphereField() {
    RenderSceneBuilder b;
    b.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
    MaterialId grey = b.addMaterial(Material::lambertian("grey", Vec3f(0.6f)));
    MaterialId ground = b.addMaterial(Material::lambertian("ground", Vec3f(0.3f, 0.28f, 0.25f)));
    MaterialId tints[] = {kNoMaterial, b.addMaterial(Material::lambertian("red", Vec3f(0.7f, 0.2f, 0.15f))),
                          b.addMaterial(Material::lambertian("green", Vec3f(0.2f, 0.6f, 0.2f))),
                          b.addMaterial(Material::lambertian("blue", Vec3f(0.15f, 0.25f, 0.7f)))};

    constexpr int kColumns = 40, kRows = 25;
    constexpr float kSpacing = 3, kRadius = 1.2f;
    ShapeSpec ball{ShapeKind::Sphere};
    ball.radius = kRadius;
    ball.segments = 100;
    ball.rings = 51;  // 100 x 51 gives 10,000 triangles, as in instances-10k
    Mesh sphere = makeShape(ball);
    sphere.setMaterial(grey);
    PrototypeId prototype = b.addPrototype(std::move(sphere));

    Vec3f centre{kSpacing * (kColumns - 1) / 2, kSpacing * (kRows - 1) / 2, 0};
    ShapeSpec plane{ShapeKind::Plane};
    plane.size = {kSpacing * (kColumns + 4), kSpacing * (kRows + 4), 0};
    Mesh floor = makeShape(plane);
    floor.setMaterial(ground);
    b.addMesh(floor, Transform::translate(centre), 1);
    for (int i = 0; i < kColumns * kRows; ++i) {
        Vec3f at{kSpacing * float(i % kColumns), kSpacing * float(i / kColumns), kRadius};
        b.addInstance({Transform::translate(at), prototype, tints[i % 4], ObjectId(2 + i)});
    }

    Camera camera;
    camera.position = {centre.x, -30, 55};
    camera.lookAt = centre;
    camera.verticalFovDegrees = 50;
    camera.width = 1920;
    camera.height = 1080;
    b.setCamera(camera);
    Environment sky;
    sky.radiance = Vec3f(0.4f, 0.5f, 0.7f);
    b.setEnvironment(sky);
    return std::move(b).build();
}

struct BenchScene {
    const char *name;
    RenderScene (*make)();
    std::unique_ptr<RenderScene> scene;
    std::unique_ptr<OsMesaRenderer> osmesa;

    // Scenes and contexts are made on first use, so a filtered run builds only what it needs.
    const RenderScene &get() {
        if (!scene) scene = std::make_unique<RenderScene>(make());
        return *scene;
    }
    OsMesaRenderer &renderer() {
        if (!osmesa) osmesa = std::make_unique<OsMesaRenderer>(get());
        return *osmesa;
    }
};

BenchScene gScenes[] = {
    {"default", [] { return fileScene("", 1280, 720); }, nullptr, nullptr},
    {"spheres-10M", sphereField, nullptr, nullptr},
    {"instances-10k", [] { return fileScene(VEDUTA_SOURCE_DIR "/scenes/bench/instances-10k.xml", 1920, 1080); },
     nullptr, nullptr},
};

// What the OSMesa renderer draws: Shaded, no shadows, no culling, no wireframe.
PreviewOptions shadedOptions() {
    PreviewOptions options;
    options.mode = PreviewMode::Shaded;
    return options;
}

void BM_Preview(benchmark::State &state, BenchScene *b) {
    const RenderScene &scene = b->get();
    PreviewOptions options = shadedOptions();
    tbb::task_arena arena(kThreads);
    arena.initialize();
    for (auto _ : state) {
        arena.execute([&] { benchmark::DoNotOptimize(renderPreview(scene, options)); });
    }
    state.counters["triangles"] = double(scene.effectiveTriangleCount());
}

void BM_OsMesa(benchmark::State &state, BenchScene *b) {
    OsMesaRenderer &renderer = b->renderer();
    for (auto _ : state) renderer.drawFrame();
    state.counters["triangles"] = double(b->get().effectiveTriangleCount());
}

int srgb8(float linear) { return int(std::lround(linearToSrgb(linear) * 255.0f)); }

// The share of pixels where some channel differs by more than 8 in 8-bit sRGB, as the PNGs
// would show them; `diff` marks them red over a dimmed copy of `a`.
double mismatchFraction(const RgbaImage &a, const RgbaImage &b, RgbaImage *diff) {
    size_t mismatched = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            size_t p = (size_t(y) * size_t(a.width()) + size_t(x)) * 4;
            bool differs = false;
            for (size_t c = 0; c < 3; ++c) differs |= std::abs(srgb8(a.rgba()[p + c]) - srgb8(b.rgba()[p + c])) > 8;
            mismatched += differs;
            Vec3f dimmed = Vec3f(a.rgba()[p], a.rgba()[p + 1], a.rgba()[p + 2]) * 0.25f;
            if (diff) diff->set(x, y, differs ? Vec3f(1, 0, 0) : dimmed);
        }
    }
    return double(mismatched) / (double(a.width()) * double(a.height()));
}

// Renders both once more outside any timing, prints how far they agree and, with --images,
// writes preview_<scene>.png, osmesa_<scene>.png and diff_<scene>.png.
void compareImages(BenchScene &b, const std::string &imageFolder) {
    tbb::task_arena arena(kThreads);
    PreviewImage preview = arena.execute([&] { return renderPreview(b.get(), shadedOptions()); });
    b.renderer().drawFrame();
    RgbaImage gl = b.renderer().image();
    RgbaImage diff(gl.width(), gl.height());
    double fraction = mismatchFraction(preview.film, gl, &diff);
    std::printf("scene %s: %.3f %% of pixels differ by more than 8/255 in sRGB", b.name, 100.0 * fraction);
    if (!imageFolder.empty()) {
        std::filesystem::path folder(imageFolder);
        std::filesystem::create_directories(folder);
        writePng(preview.film, folder / (std::string("preview_") + b.name + ".png"));
        writePng(gl, folder / (std::string("osmesa_") + b.name + ".png"));
        writePng(diff, folder / (std::string("diff_") + b.name + ".png"));
        std::printf(" (images in %s)", imageFolder.c_str());
    }
    std::printf("\n");
}

// Takes our own --images=DIR out of argv before Google Benchmark rejects it.
std::string takeImagesFlag(int &argc, char **argv) {
    std::string folder;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--images=", 9) == 0) {
            folder = argv[i] + 9;
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    return folder;
}

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    using namespace veduta;
    // llvmpipe reads this once, when the first context is created.
    setenv("LP_NUM_THREADS", std::to_string(kThreads).c_str(), 1);
    std::string imageFolder = takeImagesFlag(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

    for (BenchScene &b : gScenes) {
        benchmark::RegisterBenchmark((std::string("BM_Preview/") + b.name).c_str(), BM_Preview, &b)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark((std::string("BM_OsMesa/") + b.name).c_str(), BM_OsMesa, &b)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    MedianReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    bool describedGl = false;
    for (BenchScene &b : gScenes) {
        const auto *previewRun = reporter.find(std::string("BM_Preview/") + b.name);
        const auto *glRun = reporter.find(std::string("BM_OsMesa/") + b.name);
        if (!previewRun || !glRun) continue;
        double previewMs = previewRun->GetAdjustedRealTime(), glMs = glRun->GetAdjustedRealTime();
        if (!describedGl) {
            std::printf("\nllvmpipe: %s, LP_NUM_THREADS=%d; preview: TBB arena of %d\n",
                        b.renderer().description().c_str(), kThreads, kThreads);
            describedGl = true;
        }
        std::printf(
            "scene %s (%llu triangles, %dx%d): preview %.2f ms, llvmpipe %.2f ms, "
            "ratio preview/llvmpipe %.2f\n",
            b.name, static_cast<unsigned long long>(b.get().effectiveTriangleCount()), b.get().camera.width,
            b.get().camera.height, previewMs, glMs, previewMs / glMs);
        compareImages(b, imageFolder);
    }
    // Contexts go before exit, while llvmpipe's threads are still there to be joined.
    for (BenchScene &b : gScenes) b.osmesa.reset();
    benchmark::Shutdown();
    return 0;
}
