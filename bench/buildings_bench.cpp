// Derivation and meshing of Gründerzeit buildings (rules/gruenderzeit) on one core: lots of
// 10–22 m frontage and 12–16 m depth in rows along streets, each derived, fitted, baked and
// instanced into a RenderScene, which is then built (prototypes shared, tangents computed).
// It prints buildings per second at 1,000 and 10,000 buildings, the heap the finished scene
// holds per building (glibc's mallinfo2), and time(10,000) / time(1,000). The grammar issue
// asks for ≥ 1,000 buildings/s/core, ≤ 100 KB per building at 10,000 and a ratio ≤ 11.
//
//   build/release/bench/bench_buildings [--benchmark_repetitions=5]
#include <malloc.h>

#include <cstdio>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "core/hash.h"
#include "description/material_file.h"
#include "median_reporter.h"

namespace veduta {
namespace {

struct Fixture {
    std::string folder = std::string(VEDUTA_SOURCE_DIR) + "/rules/gruenderzeit";
    const AssetLibrary &assets = AssetLibrary::builtIn();
    BuildingRules loaded{folder + "/FacadeStructure.xml"};
    const RuleSet &rules = loaded.rules;
    const Grammar &grammar = loaded.grammar;
    std::vector<Material> materials = [this] {
        std::vector<Material> result;
        for (const MaterialDesc &desc : readMaterialFile(folder + "/materials.xml")) {
            Material m = desc.material;
            // No image is read here, but tangents must be computed as they are for the real maps.
            if (desc.normalMap.given()) m.normalMap = 0;
            result.push_back(m);
        }
        return result;
    }();
};

Fixture &fixture() {
    static Fixture f;
    return f;
}

// Lot `i`: rows of 40 lots along streets 60 m apart, frontages and depths varying per lot.
Footprint lot(uint32_t i) {
    auto frontage = [](uint32_t k) { return 10 + 12 * bitsToUnitFloat(hashValues({k, 1})); };
    uint32_t row = i / 40;
    float x = 0;
    for (uint32_t k = row * 40; k < i; ++k) x += frontage(k);
    float width = frontage(i);
    float depth = 12 + 4 * bitsToUnitFloat(hashValues({i, 2}));
    float y = float(row) * 60;
    Footprint footprint;
    footprint.points = {{x, y}, {x + width, y}, {x + width, y + depth}, {x, y + depth}};
    footprint.streetEdges = {true, false, false, false};
    return footprint;
}

struct City {
    std::vector<BuildingSpec> lots;
    explicit City(uint32_t count) {
        for (uint32_t i = 0; i < count; ++i) {
            BuildingSpec spec;
            spec.id = i + 1;
            spec.objectId = i + 1;
            spec.footprint = lot(i);
            spec.settings = SettingsStack({&fixture().rules.settings, &defaultBuildingSettings()});
            lots.push_back(std::move(spec));
        }
    }
};

// Bytes in use: from the heap arenas and in blocks mmapped on their own (large vectors).
size_t heapInUse() {
    struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

void BM_Buildings(benchmark::State &state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    Fixture &f = fixture();
    City city(uint32_t(state.range(0)));
    std::vector<std::string> warnings;
    double bytes = 0, instances = 0, triangles = 0, bakedVertices = 0, bakedTriangles = 0;
    for (auto _ : state) {
        size_t before = heapInUse();
        RenderScene scene;
        {
            RenderSceneBuilder builder;
            for (const Material &m : f.materials) builder.addMaterial(m);
            BuildingGenerator generator(f.grammar, f.assets, builder, 0);
            for (const BuildingSpec &spec : city.lots) generator.generate(spec, warnings);
            scene = std::move(builder).build();
        }
        bytes = double(heapInUse() - before);
        instances = double(scene.instances.size());
        triangles = double(scene.effectiveTriangleCount());
        bakedVertices = bakedTriangles = 0;
        for (const BakedMesh &m : scene.meshes) {
            bakedVertices += double(m.mesh.vertexCount());
            bakedTriangles += double(m.mesh.triangleCount());
        }
        state.PauseTiming();
        scene = RenderScene();
        warnings.clear();
        // Give the freed memory back, so that every iteration, of either size, starts as a fresh
        // process does: otherwise the small runs reuse pages the heap kept and the large ones,
        // whose blocks are mmapped, cannot, and the comparison measures the allocator.
        malloc_trim(0);
        state.ResumeTiming();
    }
    double n = double(state.range(0));
    state.counters["buildings/s"] = benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["KB/building"] = bytes / n / 1024;
    state.counters["instances/building"] = instances / n;
    state.counters["triangles/building"] = triangles / n;
    state.counters["baked vertices/building"] = bakedVertices / n;
    state.counters["baked triangles/building"] = bakedTriangles / n;
}

BENCHMARK(BM_Buildings)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    return veduta::benchmarkMain(argc, argv, [](const veduta::MedianReporter &reporter) {
        using namespace veduta;
        const auto *small = reporter.find("BM_Buildings/1000");
        const auto *large = reporter.find("BM_Buildings/10000");
        if (small && large) {
            double smallMs = small->GetAdjustedRealTime(), largeMs = large->GetAdjustedRealTime();
            std::printf("\none core: %.0f buildings/s at 1,000, %.0f at 10,000 (target >= 1000)\n",
                        1000 / (smallMs / 1000), 10000 / (largeMs / 1000));
            std::printf("heap per building at 10,000: %.1f KB (target <= 100)\n",
                        large->counters.at("KB/building").value);
            std::printf("time(10,000) / time(1,000) = %.2f (target <= 11)\n", largeMs / smallMs);
        }
    });
}
