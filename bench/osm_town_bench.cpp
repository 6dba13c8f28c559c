// A town from OpenStreetMap: a file of about 2,500 ways (a 12 × 12 street grid cut into ways
// at every crossing, a residential area per block and 14 buildings in each, a footway across
// every other row) written the way OSM editors write them, then imported and built into
// streets, lots and buildings as a scene's <city> is. The hardening issue asks for ≤ 10 s on
// 2 cores (median of 3); BM_OsmImport times the import alone.
//
//   build/release/bench/bench_osm_town --benchmark_repetitions=3
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/osm_import.h"
#include "median_reporter.h"

namespace veduta {
namespace {

constexpr int kBlocks = 12;                               // in each direction
constexpr double kBlockWidth = 90, kBlockDepth = 70;      // street centre to centre, metres
constexpr double kLatitude = 49.444, kLongitude = 7.769;  // Kaiserslautern

class TownWriter {
  public:
    std::string xml() {
        for (int row = 0; row <= kBlocks; ++row)
            for (int column = 0; column <= kBlocks; ++column) node(column * kBlockWidth, row * kBlockDepth);
        auto crossing = [](int column, int row) { return int64_t(row * (kBlocks + 1) + column + 1); };
        for (int row = 0; row <= kBlocks; ++row)
            for (int column = 0; column <= kBlocks; ++column) {
                if (column < kBlocks) way({crossing(column, row), crossing(column + 1, row)}, "highway", "residential");
                if (row < kBlocks) way({crossing(column, row), crossing(column, row + 1)}, "highway", "residential");
            }
        for (int row = 0; row < kBlocks; ++row)
            for (int column = 0; column < kBlocks; ++column) block(column * kBlockWidth, row * kBlockDepth);
        for (int row = 0; row < kBlocks; row += 2) {  // footways across the middle of every other row
            double y = row * kBlockDepth + kBlockDepth / 2;
            way({node(0, y), node(kBlocks * kBlockWidth, y)}, "highway", "footway");
        }
        return "<?xml version='1.0' encoding='UTF-8'?>\n<osm version=\"0.6\" generator=\"veduta bench\">\n" + nodes_ +
            ways_ + "</osm>\n";
    }
    int ways() const { return int(wayId_ - 1); }

  private:
    int64_t node(double east, double north) {
        double lat = kLatitude + north / 111'200.0,
               lon = kLongitude + east / (111'200.0 * std::cos(kLatitude * M_PI / 180));
        nodes_ += fmt::format("  <node id=\"{}\" version=\"1\" lat=\"{:.7f}\" lon=\"{:.7f}\"/>\n", nodeId_, lat, lon);
        return nodeId_++;
    }
    void way(std::vector<int64_t> refs, const char *key, const char *value, const char *more = "") {
        ways_ += fmt::format("  <way id=\"{}\" version=\"1\">\n", wayId_++);
        for (int64_t ref : refs) ways_ += fmt::format("    <nd ref=\"{}\"/>\n", ref);
        ways_ += fmt::format("    <tag k=\"{}\" v=\"{}\"/>\n{}  </way>\n", key, value, more);
    }
    void ring(double x0, double y0, double x1, double y1, const char *key, const char *value, const char *more = "") {
        int64_t a = node(x0, y0), b = node(x1, y0), c = node(x1, y1), d = node(x0, y1);
        way({a, b, c, d, a}, key, value, more);
    }
    // The residential area 4 m inside the centrelines, six houses along the front and the
    // back, one at either side.
    void block(double x, double y) {
        ring(x + 4, y + 4, x + kBlockWidth - 4, y + kBlockDepth - 4, "landuse", "residential");
        const char *levels = "    <tag k=\"building:levels\" v=\"4\"/>\n";
        for (int i = 0; i < 6; ++i) {
            double left = x + 6 + i * 12.5;
            ring(left, y + 6, left + 12, y + 16, "building", "house", levels);
            ring(left, y + kBlockDepth - 16, left + 12, y + kBlockDepth - 6, "building", "house", levels);
        }
        ring(x + 6, y + 25, x + 16, y + 37, "building", "house", levels);
        ring(x + kBlockWidth - 16, y + 25, x + kBlockWidth - 6, y + 37, "building", "house", levels);
    }

    std::string nodes_, ways_;
    int64_t nodeId_ = 1, wayId_ = 1;
};

struct Town {
    std::filesystem::path file = std::filesystem::temp_directory_path() / "veduta_bench_town.osm";
    int ways = 0;
    Town() {
        TownWriter writer;
        std::ofstream(file) << writer.xml();
        ways = writer.ways();
    }
    ~Town() { std::filesystem::remove(file); }
};

Town &town() {
    static Town t;
    return t;
}

size_t lastBuildings = 0;

void BM_OsmTown(benchmark::State &state) {
    std::string xml = fmt::format("<scene version=\"1\"><city file=\"{}\" rules=\"{}\"/></scene>", town().file.string(),
                                  VEDUTA_SOURCE_DIR "/rules/gruenderzeit/FacadeStructure.xml");
    for (auto _ : state) {
        std::vector<std::string> warnings;
        RenderScene scene = buildRenderScene(readSceneText(xml, "town.xml", VEDUTA_SOURCE_DIR), &warnings);
        std::set<uint32_t> buildings;
        for (const BakedMesh &m : scene.meshes) buildings.insert(m.buildingId);
        lastBuildings = buildings.size() - buildings.count(0);
        benchmark::DoNotOptimize(scene);
    }
    state.counters["buildings"] = double(lastBuildings);
}

void BM_OsmImport(benchmark::State &state) {
    for (auto _ : state) benchmark::DoNotOptimize(importOsm(town().file, {}));
}

BENCHMARK(BM_OsmTown)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_OsmImport)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    return veduta::benchmarkMain(argc, argv, [](const veduta::MedianReporter &reporter) {
        using namespace veduta;
        if (const auto *whole = reporter.find("BM_OsmTown"))
            std::printf("\nOSM town: %d ways, %zu buildings built in %.2f s (target <= 10 s)\n", town().ways,
                        lastBuildings, whole->GetAdjustedRealTime() / 1000);
    });
}
