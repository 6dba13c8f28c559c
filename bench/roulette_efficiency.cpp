// Which Russian roulette rule pays (p, the probability of going on, is capped at 1): each rule renders each example
// scene with several seeds; the variance across seeds (relative, as relMSE weighs it: var / (mean² + 10⁻²), averaged
// over pixels and channels) times the render time is the inverse of the rule's efficiency (1 / (variance × time),
// Veach's measure). Printed per scene against roulette off. The rule veduta uses (render_settings.h) is the one these
// figures chose; docs/performance.md has them.
//
//   build/release/bench/bench_roulette_efficiency [--res 240x135] [--spp 16] [--seeds 4]
//       [--scenes scenes/bench/blocks.xml,default,...] [--max-depth N (else each scene's)]
//       [--rounds 3 (the time is the median over rounds)]
//
// Scenes with textures need the image plugin: VEDUTA_IMAGE_PLUGIN=build/release/src/veduta-images.so.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "core/rel_mse.h"
#include "film/passes.h"
#include "render/renderer.h"

namespace veduta {
namespace {

struct Rule {
    const char *name;
    Roulette roulette;
};

constexpr uint32_t kNever = 1u << 30;

// veduta's rule before it was measured was "from 3, p = min(0.95, max beta)": threshold 1.
const Rule kRules[] = {
    {"off", {kNever, 1}},
    {"from 3, p = max beta", {3, 1}},
    {"from 3, p = max beta / 0.5", {3, 0.5f}},
    {"from 3, p = max beta / 0.25", {3, 0.25f}},
    {"from 3, p = max beta / 0.1", {3, 0.1f}},
    {"from 3, p = max beta / 0.05", {3, 0.05f}},
    {"from 1, p = max beta / 0.1", {1, 0.1f}},
};

struct Measurement {
    double relVariance = 0;
    std::vector<double> seconds;  // one per round

    double medianSeconds() const {
        std::vector<double> sorted = seconds;
        std::sort(sorted.begin(), sorted.end());
        return sorted[sorted.size() / 2];
    }
};

// One round: the render time over all seeds, and the images. The sampler's seed and the
// roulette change nothing of the scene, so one is built for all.
double renderSeeds(RenderScene &scene, const Bvh &bvh, const Roulette &roulette, uint32_t seeds,
                   std::vector<RgbaImage> &images) {
    scene.settings.roulette = roulette;
    images.clear();
    double seconds = 0;
    for (uint32_t seed = 1; seed <= seeds; ++seed) {
        scene.settings.seed = seed;
        RenderStats stats;
        images.push_back(combinedImage(render(scene, bvh, RenderOptions{}, &stats)));
        seconds += stats.seconds;
    }
    return seconds;
}

// Variance across the seeds' images, relative as relMSE weighs errors.
double relativeVariance(const std::vector<RgbaImage> &images) {
    const double seeds = double(images.size());
    const size_t n = images[0].pixels().size();
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; i < n; ++i) {
        if (i % 4 == 3) continue;
        double mean = 0, square = 0;
        for (const RgbaImage &image : images) {
            mean += image.pixels()[i];
            square += double(image.pixels()[i]) * image.pixels()[i];
        }
        mean /= seeds;
        double variance = (square - seeds * mean * mean) / (seeds - 1);
        sum += variance / (mean * mean + kRelMseEpsilon);
        ++count;
    }
    return sum / double(count);
}

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    using namespace veduta;
    int width = 240, height = 135;
    uint32_t spp = 16, seeds = 4, maxDepth = 0, rounds = 3;
    std::string scenes =
        VEDUTA_SOURCE_DIR "/scenes/bench/blocks.xml,default," VEDUTA_SOURCE_DIR "/scenes/gruenderzeit-street.xml";
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--res") == 0) std::sscanf(argv[i + 1], "%dx%d", &width, &height);
        if (std::strcmp(argv[i], "--spp") == 0) spp = uint32_t(std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--seeds") == 0) seeds = uint32_t(std::max(2, std::atoi(argv[i + 1])));
        if (std::strcmp(argv[i], "--scenes") == 0) scenes = argv[i + 1];
        if (std::strcmp(argv[i], "--rounds") == 0) rounds = uint32_t(std::max(1, std::atoi(argv[i + 1])));
        if (std::strcmp(argv[i], "--max-depth") == 0) maxDepth = uint32_t(std::atoi(argv[i + 1]));
    }
    for (size_t start = 0; start < scenes.size();) {
        size_t end = scenes.find(',', start);
        if (end == std::string::npos) end = scenes.size();
        std::string path = scenes.substr(start, end - start);
        start = end + 1;
        SceneDescription d = loadSceneDescription(path == "default" ? "" : path);
        d.camera.width = width;
        d.camera.height = height;
        d.settings.samplesPerPixel = spp;
        if (maxDepth) d.settings.maxDepth = maxDepth;
        std::printf("%s: %dx%d, %u spp, max depth %u, %u seeds\n", path.c_str(), width, height, spp,
                    d.settings.maxDepth, seeds);
        std::printf("  %-40s %12s %9s %11s\n", "rule", "rel. var.", "seconds", "efficiency");
        RenderScene scene = buildRenderScene(d);
        Bvh bvh(scene);
        // Rounds interleave the rules, so that a slower spell of the machine hits them alike.
        std::vector<Measurement> measured(std::size(kRules));
        std::vector<RgbaImage> images;
        for (uint32_t round = 0; round < rounds; ++round) {
            for (size_t r = 0; r < std::size(kRules); ++r) {
                measured[r].seconds.push_back(renderSeeds(scene, bvh, kRules[r].roulette, seeds, images));
                if (round == 0) measured[r].relVariance = relativeVariance(images);
            }
        }
        const Measurement &off = measured[0];
        for (size_t r = 0; r < std::size(kRules); ++r) {
            const Measurement &m = measured[r];
            double efficiency = (off.relVariance * off.medianSeconds()) / (m.relVariance * m.medianSeconds());
            std::printf("  %-40s %12.6g %9.2f %10.2fx\n", kRules[r].name, m.relVariance, m.medianSeconds(), efficiency);
        }
    }
    return 0;
}
