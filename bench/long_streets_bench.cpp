// The street shapes that once cost the square of their size (the hardening issue): a block of
// 2,000 edges inside a ring street of 2,000 segments, and one street of 800 segments, each a
// CityData file built into streets, lots and buildings as a scene's <city> is. The issue asks
// for ≤ 2 s each on 2 cores (median of 3).
//
//   build/release/bench/bench_long_streets --benchmark_repetitions=3
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "median_reporter.h"

namespace veduta {
namespace {

struct Point2 {
    double e, n;
};

// A CityData file: the points, the streets from point to point along `street` (closed when
// asked), and one block of the given points without lots.
std::string cityData(const std::vector<Point2> &street, bool closed, const std::vector<Point2> &block) {
    std::string points, streets, blockPoints;
    for (size_t i = 0; i < street.size(); ++i)
        points += fmt::format("<Point id=\"{}\" e=\"{:.3f}\" n=\"{:.3f}\"/>\n", i, street[i].e, street[i].n);
    for (size_t i = 0; i < block.size(); ++i) {
        size_t id = street.size() + i;
        points += fmt::format("<Point id=\"{}\" e=\"{:.3f}\" n=\"{:.3f}\"/>\n", id, block[i].e, block[i].n);
        blockPoints += fmt::format("<Point id=\"{}\"/>", id);
    }
    size_t count = closed ? street.size() : street.size() - 1;
    for (size_t i = 0; i < count; ++i)
        streets +=
            fmt::format("<Street id=\"{}\" startPoint=\"{}\" endPoint=\"{}\"/>\n", i, i, (i + 1) % street.size());
    std::string blocks = block.empty() ? "" : "<Blocks><Block><Points>" + blockPoints + "</Points></Block></Blocks>\n";
    return fmt::format(
        "<CityData>\n<Points>\n{}</Points>\n<StreetNetwork><Streets>\n{}</Streets><Width>6</Width>"
        "</StreetNetwork>\n{}<Rulefiles><Rulefile>{}</Rulefile></Rulefiles>\n</CityData>\n",
        points, streets, blocks, VEDUTA_SOURCE_DIR "/rules/gruenderzeit/FacadeStructure.xml");
}

std::vector<Point2> circle(double radius, int points) {
    std::vector<Point2> ring;
    for (int i = 0; i < points; ++i) {
        double a = 2 * M_PI * i / points;
        ring.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return ring;
}

// A gentle S-curve of `segments` segments of about 2 m.
std::vector<Point2> curve(int segments) {
    std::vector<Point2> line;
    for (int i = 0; i <= segments; ++i) line.push_back({2.0 * i, 40 * std::sin(i * 2 * M_PI / segments)});
    return line;
}

class CityFile {
  public:
    CityFile(const std::string &name, const std::string &xml) : file_(std::filesystem::temp_directory_path() / name) {
        std::ofstream(file_) << xml;
    }
    ~CityFile() { std::filesystem::remove(file_); }
    const std::filesystem::path &path() const { return file_; }

  private:
    std::filesystem::path file_;
};

void build(benchmark::State &state, const CityFile &city) {
    std::string xml = fmt::format("<scene version=\"1\"><city file=\"{}\"/></scene>", city.path().string());
    for (auto _ : state) {
        std::vector<std::string> warnings;
        benchmark::DoNotOptimize(buildRenderScene(readSceneText(xml, "streets.xml", VEDUTA_SOURCE_DIR), &warnings));
    }
}

void BM_RingBlock2000(benchmark::State &state) {
    static const CityFile city("veduta_bench_ring.xml", cityData(circle(300, 2000), true, circle(290, 2000)));
    build(state, city);
}

void BM_Street800(benchmark::State &state) {
    static const CityFile city("veduta_bench_street.xml", cityData(curve(800), false, {}));
    build(state, city);
}

BENCHMARK(BM_RingBlock2000)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_Street800)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    return veduta::benchmarkMain(argc, argv, [](const veduta::MedianReporter &reporter) {
        using namespace veduta;
        for (const char *name : {"BM_RingBlock2000", "BM_Street800"})
            if (const auto *run = reporter.find(name))
                std::printf("%s: %.2f s (target <= 2 s)\n", name, run->GetAdjustedRealTime() / 1000);
    });
}
