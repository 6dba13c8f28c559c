// Tree placement and tree prototypes: a square kilometre of forest at 5 m (the budget is
// 0.5 s for about 35 000 trees) and the meshing of one prototype.
#include <benchmark/benchmark.h>

#include "geo/tree_models.h"
#include "geo/tree_placement.h"

namespace veduta {
namespace {

void BM_PlantSquareKilometre(benchmark::State &state) {
    TreeStand stand = treeStand(LandClass::Forest, TreeKind::Mixed);
    stand.spacing = 5;
    const std::vector<Vec2f> ring = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
    size_t trees = 0;
    for (auto _ : state) {
        TreeSet set;
        plantArea(set, ring, stand, 1, 1);
        trees = set.trees.size();
        benchmark::DoNotOptimize(set.trees.data());
    }
    state.counters["trees"] = double(trees);
}
BENCHMARK(BM_PlantSquareKilometre)->Unit(benchmark::kMillisecond);

void BM_TreeModel(benchmark::State &state) {
    auto kind = TreeKind(state.range(0));
    size_t triangles = 0;
    uint32_t seed = 0;
    for (auto _ : state) {
        Mesh m = treeModel(kind, seed % kTreeVariants, seed, {0, 1});
        triangles += m.triangleCount();
        ++seed;
    }
    state.counters["triangles"] = double(triangles) / double(seed);
}
BENCHMARK(BM_TreeModel)->Arg(int(TreeKind::Broadleaf))->Arg(int(TreeKind::Conifer))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace veduta

BENCHMARK_MAIN();
