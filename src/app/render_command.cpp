#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/display_options.h"
#include "app/exr_options.h"
#include "app/number_option.h"
#include "app/render_metadata.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "film/passes.h"
#include "io/checkpoint_file.h"
#include "io/exr_file.h"
#include "io/output_files.h"
#include "render/bvh.h"
#include "render/renderer.h"
#include "scene/scene_hash.h"

namespace veduta {

namespace {

struct RenderArgs {
    std::string scene;
    std::string exr;
    std::string png;
    ExrArgs exrArgs;
    DisplayImageOptions display;
    std::optional<uint32_t> spp, seed, maxDepth, tileSize, minSamples;
    std::optional<float> noiseThreshold;
    std::string resolution;
    std::vector<int> region;
    uint32_t sampleOffset = 0;
    double timeLimit = 0;
    double checkpointEvery = 0;
    std::string checkpoint;
    bool resume = false;
    unsigned threads = 0;
    bool quiet = false;
};

void applyOverrides(const RenderArgs &args, SceneDescription &d) {
    if (args.spp) d.settings.samplesPerPixel = *args.spp;
    if (args.seed) replaceEverySeed(d, *args.seed);
    if (args.maxDepth) d.settings.maxDepth = *args.maxDepth;
    if (args.tileSize) d.settings.tileSize = *args.tileSize;
    if (args.noiseThreshold) d.settings.noiseThreshold = *args.noiseThreshold;
    if (args.minSamples) d.settings.minSamples = *args.minSamples;
    applyResolution(args.resolution, d.camera);
}

PixelWindow regionOf(const RenderArgs &args, const Camera &camera) {
    if (args.region.empty()) return {};
    PixelWindow w{args.region[0], args.region[1], args.region[2], args.region[3]};
    if (w.empty() || !PixelWindow{0, 0, camera.width, camera.height}.contains(w)) {
        throw InputError(FileLoc{"--region"},
                         fmt::format("{} {} {} {} is not a window inside the {}x{} image (X0 Y0 X1 Y1, X1 and Y1 "
                                     "excluded)",
                                     w.x0, w.y0, w.x1, w.y1, camera.width, camera.height));
    }
    return w;
}

// What must be the same for a checkpoint to continue this render.
RenderIdentity identityOf(const RenderScene &scene, const Film &film, const RenderOptions &options, uint64_t hash) {
    const PixelWindow &w = film.window();
    const RenderSettings &s = scene.settings;
    return {{"scene", hashText(hash)},
            {"image", fmt::format("{}x{}", film.fullWidth(), film.fullHeight())},
            {"region", fmt::format("{} {} {} {}", w.x0, w.y0, w.x1, w.y1)},
            {"samples", std::to_string(s.samplesPerPixel)},
            {"sample offset", std::to_string(options.sampleOffset)},
            {"seed", std::to_string(s.seed)},
            {"max depth", std::to_string(s.maxDepth)},
            {"noise threshold", fmt::format("{}", s.noiseThreshold)},
            {"min samples", std::to_string(s.minSamples)},
            {"cryptomatte ranks", std::to_string(film.cryptomatteRanks())}};
}

DevelopOptions developOptionsOf(const ExrArgs &args, const RenderScene &scene) {
    DevelopOptions options;
    options.passes = args.passes;
    options.rgba = args.rgba;
    if (args.wantsCryptomatte()) options.naming = cryptomatteNaming(scene);
    return options;
}

// Writes a checkpoint after a pass once `every` seconds have passed since the last.
class Checkpoints {
  public:
    Checkpoints(std::filesystem::path file, RenderIdentity identity, double every) :
        file_(std::move(file)), identity_(std::move(identity)), every_(every), last_(Clock::now()) {}

    void afterPass(Film &film, const RenderStats &stats) {
        if (std::chrono::duration<double>(Clock::now() - last_).count() < every_) return;
        writeCheckpoint(file_, identity_, film, stats);
        last_ = Clock::now();
    }

  private:
    using Clock = std::chrono::steady_clock;
    std::filesystem::path file_;
    RenderIdentity identity_;
    double every_;
    Clock::time_point last_;
};

void printSummary(const std::string &exr, const RenderArgs &args, const Film &film, const RenderStats &stats) {
    uint64_t samples = 0;
    for (size_t p = 0; p < film.pixelCount(); ++p) samples += film.sampleCount(p);
    std::string also;
    for (const std::string &file : {args.png, args.display.file}) {
        if (!file.empty()) also += ", " + file;
    }
    std::fprintf(stderr, "%s: %dx%d, %.4g spp, %.2f s, %.2f Mrays/s%s\n", exr.c_str(), film.window().width(),
                 film.window().height(), double(samples) / double(film.pixelCount()), stats.seconds,
                 double(stats.rays.total()) / stats.seconds * 1e-6, also.c_str());
}

void runRender(const RenderArgs &args) {
    auto threadLimit = limitThreads(args.threads);
    std::string exr = args.exr.empty() ? defaultOutput(args.scene, ".exr") : args.exr;
    std::filesystem::path checkpoint = args.checkpoint.empty() ? exr + ".checkpoint" : args.checkpoint;
    prepareOutputFile(exr);
    if (!args.png.empty()) prepareOutputFile(args.png);
    if (args.checkpointEvery > 0) prepareOutputFile(checkpoint);
    checkDisplayOptions(args.display);
    SceneDescription description = loadSceneDescription(args.scene);
    applyOverrides(args, description);
    RenderScene scene = buildSceneWithWarnings(description);
    const uint64_t hash = sceneHash(scene);

    RenderOptions options;
    options.showProgress = !args.quiet;
    options.region = regionOf(args, scene.camera);
    options.sampleOffset = args.sampleOffset;
    options.timeLimitSeconds = args.timeLimit;
    Film film = makeFilm(scene, options);
    if (args.exrArgs.wantsCryptomatte()) film.enableCryptomatte(args.exrArgs.cryptomatteRanks);
    RenderIdentity identity = identityOf(scene, film, options, hash);
    RenderStats stats;
    if (args.resume && std::filesystem::exists(checkpoint)) {
        readCheckpoint(checkpoint, identity, film, stats);
        if (!args.quiet) {
            std::fprintf(stderr, "veduta: resuming from %s after %u of %u samples\n", checkpoint.c_str(),
                         stats.samplesDone, scene.settings.samplesPerPixel);
        }
    } else if (args.resume && !args.quiet) {
        std::fprintf(stderr, "veduta: no checkpoint at %s, starting afresh\n", checkpoint.c_str());
    }
    Checkpoints checkpoints(checkpoint, identity, args.checkpointEvery);
    if (args.checkpointEvery > 0) {
        options.afterPass = [&](Film &f, const RenderStats &s) { checkpoints.afterPass(f, s); };
    }

    Bvh bvh(scene);
    renderFilm(scene, bvh, options, film, stats);

    LayeredImage image = developFilm(film, developOptionsOf(args.exrArgs, scene));
    addRenderMetadata(image, args.scene, description, scene, options, stats, hash);
    OutputSet outputs({exr, args.png, args.display.file});
    writeExr(image, exr, exrFormatOf(args.exrArgs, image));
    RgbaImage combined = combinedImage(film);
    if (!args.png.empty()) writePng(combined, args.png);
    writeDisplayImage(combined, args.display);
    outputs.commit();
    // The checkpoint has served once the image is safely written.
    std::error_code ignored;
    std::filesystem::remove(checkpoint, ignored);
    if (stats.nonFiniteSamples) {
        std::fprintf(stderr, "veduta: warning: %llu samples were not finite and counted as black\n",
                     (unsigned long long)stats.nonFiniteSamples);
    }
    if (!args.quiet) printSummary(exr, args, film, stats);
}

}  // namespace

void addRenderCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App *cmd = app.add_subcommand("render", "Path-trace a scene to a multilayer OpenEXR (and display images)");
    addSceneArgument(*cmd, args->scene);
    cmd->add_option("-o,--output", args->exr, "EXR file to write [renders/<scene name>.exr]")
        ->check(fileWithExtension(".exr"));
    cmd->add_option("--png", args->png, "Also write an 8-bit sRGB PNG here")->check(fileWithExtension(".png"));
    addExrOptions(*cmd, args->exrArgs);
    addDisplayOptions(*cmd, args->display);
    cmd->add_option("--spp,--samples", args->spp, "Samples per pixel (overrides the scene)")
        ->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--sample-offset", args->sampleOffset,
                    "Take samples K … K+N−1 of each pixel's sequence, for `veduta merge` [0]")
        ->check(CLI::Range(0u, 1u << 24));
    cmd->add_option("--region", args->region, "Render only pixels X0 ≤ x < X1, Y0 ≤ y < Y1 (EXR data window)")
        ->expected(4)
        ->type_name("X0 Y0 X1 Y1");
    cmd->add_option("--seed", args->seed,
                    "Seed of every random choice: the sampler's, the buildings', the city's and the landscape's "
                    "(replaces <scene seed> and every seed the file gives an element)");
    cmd->add_option("--max-depth", args->maxDepth, "Longest path, in bounces (overrides the scene)")
        ->check(CLI::Range(1u, 1024u));
    cmd->add_option("--noise-threshold", args->noiseThreshold,
                    "Adaptive sampling: a pixel stops once its relative deviation over its samples falls "
                    "below this (e.g. 0.001; 0 = off)")
        ->check(finiteIn(0, 1e6));
    cmd->add_option("--min-spp", args->minSamples, "Adaptive sampling: samples before the first check [automatic]")
        ->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--time-limit", args->timeLimit, "Stop after the last pass that ends within SECONDS")
        ->check(finiteIn(1e-3, 1e9));
    cmd->add_option("--checkpoint-every", args->checkpointEvery, "Write a checkpoint after a pass every SECONDS")
        ->check(finiteIn(1e-3, 1e9));
    cmd->add_option("--checkpoint", args->checkpoint, "Checkpoint file [<output>.checkpoint]");
    cmd->add_flag("--resume", args->resume, "Continue from the checkpoint if there is one");
    cmd->add_option("--tile", args->tileSize, "Tile size in pixels; changes speed, never the image")
        ->check(CLI::Range(1u, 4096u));
    addResolutionOption(*cmd, args->resolution);
    addThreadsOption(*cmd, args->threads);
    cmd->add_flag("-q,--quiet", args->quiet, "No progress bar and no summary");
    cmd->callback([args, &exitCode] {
        checkCompression(args->exrArgs);
        exitCode = runGuarded([&] { runRender(*args); });
    });
}

}  // namespace veduta
