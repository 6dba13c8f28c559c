// A square kilometre of Gründerzeit district generated from nothing but its street grid: lots
// cut round courtyards behind the sidewalks, buildings derived with rules/gruenderzeit, roofs
// of four kinds, street surfaces, and the RenderScene built. The city issue asks for about
// 1,500 buildings in ≤ 5 s on 2 cores (Schrader's thesis needed 950 s in 2007). BM_District
// times the whole of generateCity plus the scene build; the others time its phases alone on
// the same district, so that the printed split shows where the time goes.
//
//   build/release/bench/bench_district [--benchmark_repetitions=5]
#include <cstdio>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "block_grid.h"
#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/generate_city.h"
#include "city/roof_choice.h"
#include "description/material_file.h"
#include "median_reporter.h"

namespace veduta {
namespace {

constexpr int kColumns = 8, kRows = 10;  // blocks of 125 × 100 m: 1 km × 1 km
constexpr uint32_t kSeed = 1871;

CityData district() { return gruenderzeitGrid(kColumns, kRows); }

struct Fixture {
    CityData city = district();
    StreetNetwork streets = streetNetworkOf(city);
    BuildingRules loaded{city.ruleFiles.front()};
    std::vector<Material> materials = gruenderzeitMaterials();
    // Every block's settings and lots, as generateCity makes them.
    std::vector<SettingsStack> blockSettings;
    std::vector<std::vector<IdentifiedLot>> lots;
    Fixture() {
        for (const CityBlock &block : city.blocks) {
            blockSettings.push_back(settingsFor(city, block, nullptr, loaded.rules.settings));
            lots.push_back(lotsOf(block, streets, blockSettings.back(), kSeed));
        }
    }
    size_t buildings() const {
        size_t count = 0;
        for (const auto &block : lots) count += block.size();
        return count;
    }
};

Fixture &fixture() {
    static Fixture f;
    return f;
}

RenderSceneBuilder builderWithMaterials() {
    RenderSceneBuilder builder;
    for (const Material &m : fixture().materials) builder.addMaterial(m);
    return builder;
}

void BM_District(benchmark::State &state) {
    Fixture &f = fixture();
    uint32_t built = 0;
    for (auto _ : state) {
        RenderSceneBuilder builder = builderWithMaterials();
        std::vector<std::string> warnings;
        built = generateCity(f.city, kSeed, 1, builder, warnings);
        benchmark::DoNotOptimize(std::move(builder).build());
    }
    state.counters["buildings"] = built;
}

void BM_Streets(benchmark::State &state) {
    for (auto _ : state) benchmark::DoNotOptimize(streetGeometry(fixture().streets));
}

void BM_Lots(benchmark::State &state) {
    Fixture &f = fixture();
    for (auto _ : state) {
        for (uint32_t b = 0; b < f.city.blocks.size(); ++b)
            benchmark::DoNotOptimize(lotsOf(f.city.blocks[b], f.streets, f.blockSettings[b], kSeed));
    }
}

void BM_Roofs(benchmark::State &state) {
    Fixture &f = fixture();
    for (auto _ : state) {
        for (size_t b = 0; b < f.lots.size(); ++b) {
            for (const IdentifiedLot &lot : f.lots[b]) {
                uint32_t id = cityBuildingId(1, lot.identity);
                BuildingHeights heights = randomiseHeights(f.blockSettings[b], kSeed, id);
                RoofOptions options = roofOptionsFor(lot.footprint, f.blockSettings[b], heights, kSeed, id);
                const Footprint &ground = lot.footprint;
                benchmark::DoNotOptimize(buildRoof({ground.points, {}, ground.base}, heights.building, options));
            }
        }
    }
}

// Facades and roofs of every building, without lots, streets or the scene build.
void BM_Buildings(benchmark::State &state) {
    Fixture &f = fixture();
    for (auto _ : state) {
        RenderSceneBuilder builder = builderWithMaterials();
        BuildingGenerator generator(f.loaded.grammar, AssetLibrary::builtIn(), builder, kSeed);
        std::vector<std::string> warnings;
        for (size_t b = 0; b < f.lots.size(); ++b) {
            for (const IdentifiedLot &lot : f.lots[b]) {
                BuildingSpec spec;
                spec.id = cityBuildingId(1, lot.identity);
                spec.objectId = 1;
                spec.footprint = lot.footprint;
                spec.settings = f.blockSettings[b];
                generator.generate(spec, warnings);
            }
        }
        state.PauseTiming();
        builder = RenderSceneBuilder();
        state.ResumeTiming();
    }
}

BENCHMARK(BM_District)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Streets)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Lots)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Roofs)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Buildings)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    return veduta::benchmarkMain(argc, argv, [](const veduta::MedianReporter &reporter) {
        using namespace veduta;
        const auto *whole = reporter.find("BM_District");
        if (whole) {
            double total = whole->GetAdjustedRealTime();
            std::printf("\n1 km² district: %zu buildings on %zu blocks in %.2f s (target <= 5 s)\n",
                        fixture().buildings(), fixture().city.blocks.size(), total / 1000);
            std::printf("phases, each timed alone:");
            for (const char *phase : {"BM_Streets", "BM_Lots", "BM_Roofs", "BM_Buildings"}) {
                if (const auto *run = reporter.find(phase))
                    std::printf("  %s %.0f ms (%.0f%%)", phase + 3, run->GetAdjustedRealTime(),
                                100 * run->GetAdjustedRealTime() / total);
            }
            std::printf("\n(Buildings includes Roofs; the rest of District is the scene build.)\n");
        }
    });
}
