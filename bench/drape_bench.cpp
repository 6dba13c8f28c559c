// Draping ~200 ATKIS-like areas on a 1000 × 1000 DGM, building the terrain surface and draping
// roads on it (issue 8: a couple of seconds at most on 2 cores).
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/hash.h"
#include "geo/drape_areas.h"
#include "geo/ribbons.h"
#include "geo/terrain_surface.h"

namespace veduta {
namespace {

double unit(uint32_t seed, uint32_t i) { return double(hashValues({seed, i})) * 0x1p-32; }

const LocalFrame kFrame{{3392500, 5588500}};

HeightGrid bigGrid() {
    HeightGrid grid;
    grid.west = 3392000, grid.south = 5588000, grid.spacing = 1.0, grid.columns = 1000, grid.rows = 1000;
    grid.heights.resize(1000 * 1000);
    for (int r = 0; r < 1000; ++r) {
        for (int c = 0; c < 1000; ++c) {
            grid.node(c, r) =
                float(200 + 20 * std::sin(c / 37.0) * std::cos(r / 23.0) + 0.05 * c + unit(1, uint32_t(r * 1000 + c)));
        }
    }
    return grid;
}

// 200 star-shaped areas of 40–120 points, 15–80 m across, overlapping, every class.
std::vector<DrapeArea> manyAreas(const HeightGrid &grid) {
    std::vector<DrapeArea> areas;
    LandClass classes[] = {LandClass::Forest,    LandClass::Farmland, LandClass::Settlement,
                           LandClass::Grassland, LandClass::Park,     LandClass::Shrubs,
                           LandClass::Water,     LandClass::Other,    {}};
    for (uint32_t i = 0; i < 200; ++i) {
        double cx = grid.west + 1000 * unit(2, i), cy = grid.south + 1000 * unit(3, i), radius = 15 + 65 * unit(4, i);
        int points = 40 + int(80 * unit(5, i));
        MapRing ring;
        for (int k = 0; k < points; ++k) {
            double angle = 2 * M_PI * k / points, r = radius * (0.6 + 0.4 * unit(6 + i, uint32_t(k)));
            ring.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
        }
        areas.push_back({ring, classes[i % 8], i, {}});
    }
    return areas;
}

void drapeTwoHundredAreas(benchmark::State &state) {
    HeightGrid grid = bigGrid();
    std::vector<DrapeArea> areas = manyAreas(grid);
    size_t triangles = 0;
    for (auto _ : state) {
        DrapedTerrain terrain = drapeAreas(grid, kFrame, areas, {});
        triangles = terrain.mesh.triangleCount();
        benchmark::DoNotOptimize(terrain);
    }
    state.counters["triangles"] = double(triangles);
}
BENCHMARK(drapeTwoHundredAreas)->Unit(benchmark::kMillisecond)->UseRealTime();

void surfaceAndRibbons(benchmark::State &state) {
    HeightGrid grid = bigGrid();
    DrapedTerrain terrain = drapeAreas(grid, kFrame, manyAreas(grid), {});
    std::vector<MapLine> roads;
    for (uint32_t i = 0; i < 50; ++i) {  // 50 roads of 1 km
        MapLine line;
        for (int k = 0; k <= 100; ++k) {
            line.push_back({grid.west + 10 * k * 0.98 + 5, grid.south + 20 * i + 10 + 8 * std::sin(k / (3.0 + i % 5))});
        }
        roads.push_back(line);
    }
    for (auto _ : state) {
        TerrainSurface surface(terrain.mesh, gridLines(grid, kFrame));
        size_t triangles = 0;
        for (const MapLine &road : roads) triangles += drapeRibbon(road, 6, surface, kFrame, {}).triangleCount();
        benchmark::DoNotOptimize(triangles);
    }
}
BENCHMARK(surfaceAndRibbons)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace veduta

BENCHMARK_MAIN();
