// Finkenzeller's masonry and cornices (issue 22, docs/facades.md) on the front of a Gründerzeit
// house: 15 × 16 m, four storeys of five 1.2 × 2 m windows and a 1.6 × 3 m door. Each masonry
// kind laid on it, the bricks baked to textures at 1 cm per texel, and the main cornice of
// Fig. 5.20 swept round a 15 × 12 m footprint. The counters are stones (or triangles) per second;
// one thread.
//
//   build/release/bench/bench_facade --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include "facade/ashlar.h"
#include "facade/brick_bond.h"
#include "facade/cyclopean.h"
#include "facade/masonry_texture.h"
#include "facade/profile.h"
#include "facade/profile_sweep.h"

namespace veduta {
namespace {

std::vector<Vec2d> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

WallFace gruenderzeitFront() {
    WallFace front{rectangle(0, 0, 15, 16), {rectangle(6.7, 0, 8.3, 3)}};
    for (int storey = 0; storey < 4; ++storey)
        for (int column = 0; column < 5; ++column) {
            if (storey == 0 && column == 2) continue;  // the door
            double x = 1.2 + 3 * column, y = 1 + 4 * storey;
            front.openings.push_back(rectangle(x, y, x + 1.2, y + 2));
        }
    return front;
}

// Fig. 5.7 with bricks of 25 × 6.25 cm (Reichsformat is 25 × 6.5).
const char *const kFigure5_7 = R"(Brick1 { 2.0, 0.5, 0.1; 206,78,51; 255,147,124; }
Brick2 { 2.0, 1.0, 0.1; 206,78,51; 255,147,124; }
Pattern { -1.0, "Brick1", "Brick2"; 0.0, "Brick1", 2.0; 1.0, "Brick1"; }
BrickMasonry { "Pattern"; 0.05; 102,102,102; })";

void countStones(benchmark::State &state, size_t stones) {
    state.counters["stones"] = double(stones);
    state.counters["stones/s"] = benchmark::Counter(double(stones), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_BrickBondWall(benchmark::State &state) {
    BrickBond bond = parseBrickBond(kFigure5_7, "figure-5.7");
    WallFace front = gruenderzeitFront();
    size_t stones = 0;
    for (auto _ : state) stones = layBrickBond(bond, front, {0.125, 1871, 1}).stones.size();
    countStones(state, stones);
}
BENCHMARK(BM_BrickBondWall)->Unit(benchmark::kMillisecond);

void BM_AshlarWall(benchmark::State &state) {
    AshlarMasonry ashlar = parseAshlarMasonry(
        "AshlarMasonry { 0.5,0.5,0.05; 1.5,0.5,0.1; 80,80,80; 100,100,90; 0.05; 110,110,110; }", "def-5.8");
    WallFace front = gruenderzeitFront();
    size_t stones = 0;
    for (auto _ : state) stones = layAshlar(ashlar, front, {0.5, 1871, 1}).stones.size();
    countStones(state, stones);
}
BENCHMARK(BM_AshlarWall)->Unit(benchmark::kMillisecond);

void BM_CyclopeanWall(benchmark::State &state) {
    CyclopeanMasonry cyclopean;
    cyclopean.spacing = 0.6;
    cyclopean.lloyd = 20;
    cyclopean.startColour = {0.3f, 0.28f, 0.25f};
    cyclopean.endColour = {0.45f, 0.42f, 0.38f};
    cyclopean.joint = 0.02;
    cyclopean.mortarColour = {0.5f, 0.5f, 0.5f};
    cyclopean.depth = 0.02;
    WallFace front = gruenderzeitFront();
    size_t stones = 0;
    for (auto _ : state) stones = cyclopeanMasonry(front, cyclopean, 1871, 1).stones.size();
    countStones(state, stones);
}
BENCHMARK(BM_CyclopeanWall)->Unit(benchmark::kMillisecond);

void BM_BakeBrickWall(benchmark::State &state) {
    WallFace front = gruenderzeitFront();
    Masonry bricks = layBrickBond(parseBrickBond(kFigure5_7, "figure-5.7"), front, {0.125, 1871, 1});
    size_t texels = 0;
    for (auto _ : state) {
        MasonryTextures textures = bakeMasonry(bricks, front, 0.01);
        texels = size_t(textures.diffuse.width) * size_t(textures.diffuse.height);
    }
    state.counters["texels"] = double(texels);
    state.counters["texels/s"] = benchmark::Counter(double(texels), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BakeBrickWall)->Unit(benchmark::kMillisecond);

void BM_SweepMainCornice(benchmark::State &state) {
    CorniceDescription cornice = parseCorniceDescription(
        R"(Modifications { line, rel, 90, 0.3; line, rel, -90, 10.0; line, rel, 90, 0.6; line, rel, -90, 11.0;
line, rel, 90, 0.6; line, rel, -90, 0.6; line, rel, 90, 0.6; line, rel, -90, 2.0; line, rel, 90, 2.0;
arc, rel, 0, -90, 4.0; line, rel, 90, 5.0; line, rel, -90, 5.0; line, rel, 90, 0.6; line, rel, -90, 0.6;
line, rel, 45, 7.0; line, rel, -45, 0.6; line, rel, 90, 0.6; line, rel, -90, 2.0; line, rel, -84, 22.0; })",
        "figure-5.20");
    ProfileOutline outline = traceProfile(cornice.profile, 10);
    ProfileOutline scaled = scaledOutline(outline, heightScale(cornice.profile, outline, 0.6));
    SweepPath footprint{rectangle(0, 0, 15, 12), 15.4, true, OutwardSide::Right};
    size_t triangles = 0;
    for (auto _ : state) triangles = sweepCornice(cornice, scaled, footprint, {}).mesh.triangleCount();
    state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_SweepMainCornice)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace veduta

BENCHMARK_MAIN();
