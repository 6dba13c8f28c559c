// Deliver 4 of issue 22 asks to bake masonry or shade it procedurally, "measure which". The same
// brick wall (gruenderzeit_front.h) three ways, one thread each:
//   * BM_BakeBrickWall: baked once to diffuse, normal and specular images at 1 cm a texel
//     (texels/s), <render masonry="baked">;
//   * BM_LookUpBakedBrickWall: what each shaded point then costs the renderer, three filtered
//     lookups of those images in the texture registry (points/s);
//   * BM_ShadeBrickWallProcedurally: what each shaded point costs veduta's procedural shader
//     (<render masonry="procedural">, points/s).
// A still pays the bake once per texel (about one a pixel, masonry_maps.h) and the lookup or the
// procedural shading at every sample that hits a wall (pixels × spp × bounces); the closing note
// of issue 22 sets these rates against the street's texels and samples.
//
//   build/release/bench/bench_masonry_shading --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "facade/brick_bond.h"
#include "facade/masonry_shader.h"
#include "facade/masonry_texture.h"
#include "gruenderzeit_front.h"
#include "io/image_library.h"

namespace veduta {
namespace {

using namespace bench;

constexpr double kTexel = 0.01;

// 65536 points over the 15 × 16 m wall: scattered (state.range(0) = 0), as a path's bounces reach
// it, or in rows (1), as a tile of camera samples does, one jittered point a cell of a 256 × 256
// grid.
std::vector<Vec2d> shadedPoints(bool inRows) {
    std::vector<Vec2d> points;
    uint32_t state = 1871;
    auto next = [&] { return double(state = state * 1664525u + 1013904223u) / 4294967296.0; };
    for (int row = 0; row < 256; ++row)
        for (int column = 0; column < 256; ++column) {
            double x = inRows ? (column + next()) / 256 : next(), y = inRows ? (row + next()) / 256 : next();
            points.push_back({15 * x, 16 * y});
        }
    return points;
}

void countPoints(benchmark::State &state, size_t points) {
    state.SetLabel(state.range(0) ? "in rows" : "scattered");
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsIterationInvariantRate);
}

Masonry frontBricks() {
    return layBrickBond(parseBrickBond(kFigure5_7, "figure-5.7"), gruenderzeitFront(), {0.125, 1871, 1});
}

void BM_BakeBrickWall(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    Masonry bricks = frontBricks();
    size_t texels = 0;
    for (auto _ : state) {
        MasonryTextures textures = bakeMasonry(bricks, front, kTexel);
        texels = size_t(textures.diffuse.width) * size_t(textures.diffuse.height);
    }
    state.counters["texels"] = double(texels);
    state.counters["texels/s"] = benchmark::Counter(double(texels), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BakeBrickWall)->Unit(benchmark::kMillisecond);

void BM_LookUpBakedBrickWall(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    MasonryTextures baked = bakeMasonry(frontBricks(), front, kTexel);
    std::filesystem::path cache = std::filesystem::temp_directory_path() / "veduta-bench-masonry-shading";
    std::shared_ptr<Textures> textures = imageLibrary().makeTextures(cache);
    int width = baked.diffuse.width, height = baked.diffuse.height;
    TextureId diffuse = textures->add(std::move(baked.diffuse)), normal = textures->add(std::move(baked.normal)),
              specular = textures->add(std::move(baked.specular));
    std::vector<Vec2d> points = shadedPoints(state.range(0) != 0);
    float footprint = float(1.0 / width);  // a pixel a texel, as the atlas is sized
    float sum = 0;
    for (auto _ : state)
        for (Vec2d p : points) {
            Vec2f uv{float(p.x / (kTexel * width)), float(p.y / (kTexel * height))};
            float values[4];
            textures->lookup(diffuse, uv, footprint, values, 4);
            sum += values[0];
            textures->lookup(normal, uv, footprint, values, 3);
            sum += values[0];
            textures->lookup(specular, uv, footprint, values, 1);
            sum += values[0];
        }
    benchmark::DoNotOptimize(sum);
    countPoints(state, points.size());
}
BENCHMARK(BM_LookUpBakedBrickWall)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Shading procedurally: veduta's MasonryShader (facade/masonry_shader.h), at a footprint under a
// stone so that every point is shaded, not a wall's mean.
void BM_ShadeBrickWallProcedurally(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    MasonryShader shader({{frontBricks(), front}});
    std::vector<Vec2d> points = shadedPoints(state.range(0) != 0);
    float sum = 0;
    for (auto _ : state)
        for (Vec2d p : points) {
            MasonrySample sample = shader.shade(shader.uvOf(0, p), float(kTexel));
            sum += sample.colour.x + sample.normal.x + sample.specular;
        }
    benchmark::DoNotOptimize(sum);
    countPoints(state, points.size());
}
BENCHMARK(BM_ShadeBrickWallProcedurally)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    // The image plugin of this build unless the caller names one.
    setenv("VEDUTA_IMAGE_PLUGIN", VEDUTA_IMAGE_PLUGIN_FILE, 0);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
