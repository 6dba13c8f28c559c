#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/display_options.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "render/bvh.h"
#include "io/output_files.h"
#include "render/renderer.h"
#include "scene/build_scene.h"

namespace veduta {

namespace {

struct RenderArgs {
    std::string scene;
    std::string exr;
    std::string png;
    DisplayImageOptions display;
    std::optional<uint32_t> spp, seed, maxDepth, tileSize;
    std::string resolution;
    unsigned threads = 0;
    bool quiet = false;
};

void applyOverrides(const RenderArgs &args, SceneDescription &d) {
    if (args.spp) d.settings.samplesPerPixel = *args.spp;
    if (args.seed) d.settings.seed = *args.seed;
    if (args.maxDepth) d.settings.maxDepth = *args.maxDepth;
    if (args.tileSize) d.settings.tileSize = *args.tileSize;
    applyResolution(args.resolution, d.camera);
}

void runRender(const RenderArgs &args) {
    auto threadLimit = limitThreads(args.threads);
    std::string exr = args.exr.empty() ? defaultOutput(args.scene, ".exr") : args.exr;
    prepareOutputFile(exr);
    if (!args.png.empty()) prepareOutputFile(args.png);
    checkDisplayOptions(args.display);
    SceneDescription description = loadSceneDescription(args.scene);
    applyOverrides(args, description);
    RenderScene scene = buildRenderScene(description);
    Bvh bvh(scene);
    RenderStats stats;
    RgbaImage film = render(scene, bvh, RenderOptions{!args.quiet}, &stats);

    writeExr(film, exr);
    if (!args.png.empty()) writePng(film, args.png);
    writeDisplayImage(film, args.display);
    if (stats.nonFiniteSamples) {
        std::fprintf(stderr, "veduta: warning: %llu samples were not finite and were dropped\n",
                     (unsigned long long)stats.nonFiniteSamples);
    }
    if (!args.quiet) {
        std::string also;
        for (const std::string &file : {args.png, args.display.file}) {
            if (!file.empty()) also += ", " + file;
        }
        std::fprintf(stderr, "%s: %dx%d, %u spp, %.2f s, %.2f Mrays/s%s\n", exr.c_str(), film.width(), film.height(),
                     scene.settings.samplesPerPixel, stats.seconds, double(stats.rays.total()) / stats.seconds * 1e-6,
                     also.c_str());
    }
}

}  // namespace

void addRenderCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App *cmd = app.add_subcommand("render", "Path-trace a scene to OpenEXR (and optionally PNG)");
    addSceneArgument(*cmd, args->scene);
    cmd->add_option("-o,--output", args->exr, "EXR file to write [renders/<scene name>.exr]")
        ->check(fileWithExtension(".exr"));
    cmd->add_option("--png", args->png, "Also write an 8-bit sRGB PNG here")->check(fileWithExtension(".png"));
    addDisplayOptions(*cmd, args->display);
    cmd->add_option("--spp", args->spp, "Samples per pixel (overrides the scene)")->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--seed", args->seed, "Seed of every random choice (overrides the scene)");
    cmd->add_option("--max-depth", args->maxDepth, "Longest path, in bounces (overrides the scene)")
        ->check(CLI::Range(1u, 1024u));
    cmd->add_option("--tile", args->tileSize, "Tile size in pixels; changes speed, never the image")
        ->check(CLI::Range(1u, 4096u));
    addResolutionOption(*cmd, args->resolution);
    addThreadsOption(*cmd, args->threads);
    cmd->add_flag("-q,--quiet", args->quiet, "No progress bar and no summary");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runRender(*args); }); });
}

}  // namespace veduta
