// Growing street networks under the local constraints (issue 20): a window seven blocks across
// of the thesis' jittered grid (rules/streets/grid.txt, blocks of 80 m), which the thesis grew
// in 770 ms on a 2010 quad core and the issue asks for in ≤ 50 ms, and the same window of the
// organic and radial rule sets, and of streets traced through a tensor field. Each run reads nothing: the rules are
// parsed once, and a run grows the word graph and the street graph from the initial word. Then a town of 10 km² (a
// window of radius 1784 m) of the grid: grown with its blocks (growCity), and grown and built
// with lots and Gründerzeit buildings (generateCity), which the issue asks for in ≤ 10 s on 2
// cores (docs/performance.md, "Building a city").
//
//   build/release/bench/bench_street_growth --benchmark_repetitions=5
#include <cmath>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "city/generate_city.h"
#include "city/grown_city.h"
#include "streets/street_builder.h"
#include "streets/street_growth.h"
#include "streets/street_rule_file.h"
#include "streets/tensor_streets.h"

namespace veduta {
namespace {

constexpr float kBlock = 80;              // the grid's street length
constexpr float kRadius = 3.5f * kBlock;  // seven blocks across
constexpr uint32_t kSeed = 2010;

void growWindow(benchmark::State &state, const char *pattern) {
    StreetRuleSet rules = readStreetRuleFile(std::filesystem::path(VEDUTA_SOURCE_DIR) / "rules" / "streets" /
                                             (std::string(pattern) + ".txt"));
    size_t edges = 0;
    for (auto _ : state) {
        SeededDraws draws(kSeed);
        WordGraph words(rules.initialWord);
        StreetBuilder streets(words);
        StreetGrowth growth(words, rules.rules, streets.nodeQuery(), draws, &streets);
        growth.grow({{0, 0}, kRadius}, {});
        edges = streets.graph().edges().size();
        benchmark::DoNotOptimize(edges);
    }
    state.counters["edges"] = double(edges);
}

void BM_GridWindow7x7(benchmark::State &state) { growWindow(state, "grid"); }
void BM_OrganicWindow(benchmark::State &state) { growWindow(state, "organic"); }
void BM_RadialWindow(benchmark::State &state) { growWindow(state, "radial"); }
BENCHMARK(BM_GridWindow7x7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OrganicWindow)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RadialWindow)->Unit(benchmark::kMillisecond);

// The same window's streets traced through the seeded tensor field (docs/tensor-streets.md).
void BM_TensorWindow(benchmark::State &state) {
    TensorField field = townField(kSeed, kRadius);
    size_t edges = 0;
    for (auto _ : state) {
        TracedStreets traced = traceStreets(field, {{0, 0}, kRadius}, {});
        edges = traced.graph.edges().size();
        benchmark::DoNotOptimize(edges);
    }
    state.counters["edges"] = double(edges);
}
BENCHMARK(BM_TensorWindow)->Unit(benchmark::kMillisecond);

const float kTownRadius = std::sqrt(10e6f / kPi);  // 10 km²

CityData grownTown(std::vector<std::string> &warnings) {
    CityGrowth growth;
    growth.radius = kTownRadius;
    growth.seed = kSeed;
    return growCity(readStreetRuleFile(std::string(VEDUTA_SOURCE_DIR) + "/rules/streets/grid.txt"), growth, warnings);
}

void BM_GrownTown10km2(benchmark::State &state) {
    size_t blocks = 0;
    for (auto _ : state) {
        std::vector<std::string> warnings;
        blocks = grownTown(warnings).blocks.size();
    }
    state.counters["blocks"] = double(blocks);
}
BENCHMARK(BM_GrownTown10km2)->Unit(benchmark::kMillisecond);

void BM_GrownTown10km2WithBuildings(benchmark::State &state) {
    uint32_t buildings = 0;
    for (auto _ : state) {
        std::vector<std::string> warnings;
        CityData town = grownTown(warnings);
        town.ruleFiles = {std::string(VEDUTA_SOURCE_DIR) + "/rules/gruenderzeit/FacadeStructure.xml"};
        RenderSceneBuilder builder;
        buildings = generateCity(town, kSeed, 1, builder, warnings);
    }
    state.counters["buildings"] = double(buildings);
}
BENCHMARK(BM_GrownTown10km2WithBuildings)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace veduta

BENCHMARK_MAIN();
