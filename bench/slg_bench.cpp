// Schrader's plans from the shipped tables (issue 21): buildings planned from their lot down to
// their rooms (sidewalk, footprint, apartments round the house corridor, rooms round each
// apartment's), block by block, on one thread; alone, and built as meshes at the storeys' level
// (the mid LOD: ≥ 1,000 SLG buildings per second per core, linear from 1,000 to 10,000)
// and with their rooms. Blocks of 110 × 90 m, slightly skewed, Table 10's land uses.
//
//   build/release/bench/bench_slg --benchmark_repetitions=5
#include <filesystem>
#include <optional>

#include <benchmark/benchmark.h>

#include "core/hash.h"
#include "slg/building_mesh.h"
#include "slg/lot_building.h"
#include "slg/subdivision.h"
#include "slg/urban_geography_file.h"

namespace veduta {
namespace {

constexpr uint32_t kSeed = 2007;

const UrbanGeography &shipped() {
    static const UrbanGeography geography =
        readUrbanGeography(std::filesystem::path(VEDUTA_SOURCE_DIR) / "rules" / "slg" / "urban-geography.xml");
    return geography;
}

// Plans the buildings of block `index` of a row of blocks, and builds them at `lod` unless none;
// returns how many it planned.
int planBlock(uint32_t index, std::optional<BuildingLod> lod, int &rooms, size_t &triangles) {
    const UrbanGeography &g = shipped();
    const Geography &block = g.blockDefaults;
    Locality locality = block.locality.value_or(Locality::Mantel);
    DominantUse use = dominantUse(blockWeights(g, block.weights));
    double skew = double(index % 7) - 3;
    Polygon2d outline = {{0, 0}, {110, 0}, {112 + skew, 90}, {-4, 88 - skew}};
    Subdivision lots =
        subdivide(outline, std::vector<EdgeLocation>(4, EdgeLocation::Street), blockPlanParameters(g, use, locality),
                  PlanRandom(kSeed, index, RandomStream::SlgPlan));
    int planned = 0;
    uint32_t lot = 0;
    for (const PlanFace *face : lots.borderFaces()) {
        uint32_t identity = hashValues({index, lot++});
        auto building = lotBuilding(g, {lotWeights(g, block.weights, parameterRandom(kSeed, identity)), locality, {}},
                                    kSeed, identity);
        if (!building) continue;
        PlanShape shape = faceShape(lots, *face);
        auto plan =
            planBuilding(shape, fourSides(shape.points, frontEdges(*face)), building->parameters, kSeed, identity);
        if (!plan) continue;
        ++planned;
        for (const ApartmentPlan &a : plan->storey.apartments) rooms += int(a.rooms.size());
        if (lod) triangles += buildingMesh(*plan, {}, *lod, {}).triangleCount();
    }
    return planned;
}

void planBuildings(benchmark::State &state, std::optional<BuildingLod> lod) {
    shipped();
    int wanted = int(state.range(0)), planned = 0, rooms = 0;
    size_t triangles = 0;
    for (auto _ : state) {
        planned = rooms = 0;
        triangles = 0;
        for (uint32_t block = 0; planned < wanted; ++block) planned += planBlock(block, lod, rooms, triangles);
    }
    state.counters["buildings"] = planned;
    state.counters["rooms"] = rooms;
    state.counters["triangles"] = double(triangles);
    state.counters["buildings_per_s"] =
        benchmark::Counter(double(planned), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SlgPlans(benchmark::State &state) { planBuildings(state, std::nullopt); }
// The "mid LOD": the outer walls storey by storey with their windows and doors.
void BM_SlgPlansAndStoreyMeshes(benchmark::State &state) { planBuildings(state, BuildingLod::Storeys); }
void BM_SlgPlansAndRoomMeshes(benchmark::State &state) { planBuildings(state, BuildingLod::Rooms); }
BENCHMARK(BM_SlgPlans)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlgPlansAndStoreyMeshes)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SlgPlansAndRoomMeshes)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace veduta

BENCHMARK_MAIN();
