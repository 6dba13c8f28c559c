// What adaptive sampling saves: the default scene (sun, sky, buildings with their shadows) is
// rendered uniformly at several sample counts and adaptively at several noise thresholds (with
// the largest uniform count as the most), each compared with a high-spp reference of another
// seed by relMSE (rel_mse.h). Uniform sampling's relMSE against its total samples is a curve;
// for each adaptive render the program reads off that curve (log-log) the total samples
// uniform sampling needs for the same relMSE and prints the saving,
// 1 − adaptive total / uniform total. The acceptance of the adaptive-sampling issue asks for
// at least 30 % at a threshold. docs/output.md ("Adaptive sampling") has the figures. About
// half a minute to a minute and a half on 2 cores, most of it the reference.
//
//   build/test/bench/bench_adaptive_sampling [--res 160x90] [--reference-spp 4096]
//       [--spp 16,32,64,128] [--thresholds 0.004,0.002,0.001,0.0005] [--min-spp N] [--scene FILE]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "assembly/build_scene.h"
#include "film/adaptive_sampling.h"
#include "film/passes.h"
#include "rel_mse.h"
#include "render/renderer.h"

namespace veduta {
namespace {

struct Run {
    std::string name;
    uint64_t samples = 0;  // over all pixels
    double relMse = 0;
    double seconds = 0;
};

std::vector<double> numberList(const char *text) {
    std::vector<double> numbers;
    for (char *end = nullptr;; ++text) {
        numbers.push_back(std::strtod(text, &end));
        text = end;
        if (*text != ',') return numbers;
    }
}

uint64_t totalSamples(const Film &film) {
    uint64_t samples = 0;
    for (size_t p = 0; p < film.pixelCount(); ++p) samples += film.sampleCount(p);
    return samples;
}

// The reference's own relMSE, from its halves: pixelNoise is √(the pixel's relMSE / n). It
// should be far below the renders' relMSE.
double referenceRelMse(const Film &film) {
    double sum = 0;
    for (size_t p = 0; p < film.pixelCount(); ++p) {
        double noise = pixelNoise(film, p);
        sum += noise * noise * film.sampleCount(p);
    }
    return sum / double(film.pixelCount());
}

Run renderRun(std::string name, RenderScene &scene, const Bvh &bvh, const RgbaImage &reference) {
    RenderStats stats;
    Film film = render(scene, bvh, {}, &stats);
    return {std::move(name), totalSamples(film), relMse(combinedImage(film), reference), stats.seconds};
}

// The total samples uniform sampling needs for `relMse`: log samples interpolated linearly in
// log relMSE between the neighbouring uniform runs (sorted by samples), the end segments
// extended beyond the first and last.
double uniformSamplesFor(double relMse, const std::vector<Run> &uniform) {
    size_t i = 0;
    while (i + 2 < uniform.size() && relMse < uniform[i + 1].relMse) ++i;
    const Run &a = uniform[i], &b = uniform[i + 1];
    double t = std::log(relMse / a.relMse) / std::log(b.relMse / a.relMse);
    return std::exp(std::log(double(a.samples)) + t * std::log(double(b.samples) / double(a.samples)));
}

std::string cpuName() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown CPU";
}

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    using namespace veduta;
    int width = 160, height = 90;
    uint32_t referenceSpp = 4096, minSamples = 0;
    std::vector<double> spps{16, 32, 64, 128}, thresholds{0.004, 0.002, 0.001, 0.0005};
    std::string sceneFile = std::string(VEDUTA_SOURCE_DIR) + "/scenes/default.xml";
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--res") == 0) std::sscanf(argv[i + 1], "%dx%d", &width, &height);
        if (std::strcmp(argv[i], "--reference-spp") == 0) referenceSpp = uint32_t(std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--spp") == 0) spps = numberList(argv[i + 1]);
        if (std::strcmp(argv[i], "--thresholds") == 0) thresholds = numberList(argv[i + 1]);
        if (std::strcmp(argv[i], "--min-spp") == 0) minSamples = uint32_t(std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--scene") == 0) sceneFile = argv[i + 1];
    }
    SceneDescription description = readSceneFile(sceneFile);
    description.camera.width = width;
    description.camera.height = height;
    RenderScene scene = buildRenderScene(description);
    Bvh bvh(scene);

    scene.settings.samplesPerPixel = referenceSpp;
    scene.settings.seed = 1000;  // independent of the test renders' samples
    RenderStats referenceStats;
    Film referenceFilm = render(scene, bvh, {}, &referenceStats);
    RgbaImage reference = combinedImage(referenceFilm);
    std::printf("%s at %dx%d; reference %u spp (seed 1000, %.1f s, its own relMSE about %.3g); %s, %u threads\n",
                sceneFile.c_str(), width, height, referenceSpp, referenceStats.seconds, referenceRelMse(referenceFilm),
                cpuName().c_str(), std::thread::hardware_concurrency());

    scene.settings.seed = 0;
    std::vector<Run> uniform;
    for (double spp : spps) {
        scene.settings.samplesPerPixel = uint32_t(spp);
        scene.settings.noiseThreshold = 0;
        uniform.push_back(renderRun(std::to_string(uint32_t(spp)) + " spp", scene, bvh, reference));
    }
    std::vector<Run> adaptive;
    scene.settings.minSamples = minSamples;
    for (double threshold : thresholds) {
        scene.settings.noiseThreshold = float(threshold);
        char name[64];
        std::snprintf(name, sizeof name, "threshold %g", threshold);
        adaptive.push_back(renderRun(name, scene, bvh, reference));
    }

    double pixels = double(width) * height;
    std::printf("%-16s %12s %9s %12s %9s %14s %8s\n", "render", "samples", "mean spp", "relMSE", "seconds",
                "uniform same", "saving");
    for (const Run &run : uniform) {
        std::printf("%-16s %12llu %9.2f %12.6g %9.2f\n", run.name.c_str(), (unsigned long long)run.samples,
                    double(run.samples) / pixels, run.relMse, run.seconds);
    }
    for (const Run &run : adaptive) {
        double same = uniformSamplesFor(run.relMse, uniform);
        bool extended = run.relMse > uniform.front().relMse || run.relMse < uniform.back().relMse;
        std::printf("%-16s %12llu %9.2f %12.6g %9.2f %14.0f %7.1f%%%s\n", run.name.c_str(),
                    (unsigned long long)run.samples, double(run.samples) / pixels, run.relMse, run.seconds, same,
                    100 * (1 - double(run.samples) / same), extended ? " (curve extended)" : "");
    }
    return 0;
}
