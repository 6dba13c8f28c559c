// A console reporter that also keeps each benchmark's median run (its only run without
// --benchmark_repetitions), for benchmark programs that print ratios between benchmarks.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

namespace veduta {

class MedianReporter : public benchmark::ConsoleReporter {
  public:
    void ReportRuns(const std::vector<Run> &runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run &run : runs) {
            bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
            bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
            if (median || single) medians_[nameOf(run)] = run;
        }
    }

    // By "function" or "function/arguments", e.g. "BM_OsMesa/default", "BM_PathTracerRays/0".
    const Run *find(const std::string &name) const {
        auto it = medians_.find(name);
        return it == medians_.end() ? nullptr : &it->second;
    }

  private:
    static std::string nameOf(const Run &run) {
        const std::string &args = run.run_name.args;
        return args.empty() ? run.run_name.function_name : run.run_name.function_name + "/" + args;
    }

    std::map<std::string, Run> medians_;
};

// The start of every benchmark program's main: Google Benchmark's options read, the
// benchmarks run with `reporter`. False when the command line has options it does not know.
inline bool runBenchmarks(int &argc, char **argv, MedianReporter &reporter) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return false;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    return true;
}

// A benchmark program's whole main: the benchmarks, then `report` prints the figures the
// program exists for from their medians. Returns main's exit code (1: an unknown option).
template <typename Report>
int benchmarkMain(int argc, char **argv, Report &&report) {
    MedianReporter reporter;
    if (!runBenchmarks(argc, argv, reporter)) return 1;
    report(reporter);
    benchmark::Shutdown();
    return 0;
}

}  // namespace veduta
