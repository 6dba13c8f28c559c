// Finkenzeller's masonry and cornices (issue 22, docs/facades.md) on the front of a Gründerzeit
// house (gruenderzeit_front.h). Each masonry kind laid on it, and the main cornice of Fig. 5.20
// swept round a 15 × 12 m footprint; masonry_shading.cpp has the bake. The counters are stones
// (or triangles) per second; one thread.
//
//   build/release/bench/bench_facade --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include "facade/ashlar.h"
#include "facade/brick_bond.h"
#include "facade/cyclopean.h"
#include "facade/profile.h"
#include "facade/profile_sweep.h"
#include "gruenderzeit_front.h"

namespace veduta {
namespace {

using namespace bench;

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
