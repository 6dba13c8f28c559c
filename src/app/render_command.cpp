#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "render/bvh.h"
#include "render/film_output.h"
#include "render/renderer.h"
#include "scene/build_scene.h"

namespace veduta {

namespace {

struct RenderArgs {
    std::string scene;
    std::string exr;
    std::string png;
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
    if (!args.resolution.empty()) std::sscanf(args.resolution.c_str(), "%dx%d", &d.camera.width, &d.camera.height);
}

// Checks a WxH resolution for CLI11: an empty string means the text is fine.
std::string checkResolution(const std::string &text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 || w > 65536 ||
        h > 65536) {
        return fmt::format("'{}' is not a resolution like 1920x1080", text);
    }
    return {};
}

std::string checkExrName(const std::string &text) {
    return std::filesystem::path(text).extension() == ".exr" ? std::string() : "the output must be an .exr file";
}

std::string checkPngName(const std::string &text) {
    return std::filesystem::path(text).extension() == ".png" ? std::string() : "the display image must be a .png file";
}

std::string defaultOutput(const std::string &scene) {
    std::string stem = scene.empty() ? "default" : std::filesystem::path(scene).stem().string();
    return "renders/" + stem + ".exr";
}

void runRender(const RenderArgs &args) {
    std::unique_ptr<tbb::global_control> threadLimit;
    if (args.threads > 0) {
        threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, args.threads);
    }
    std::string exr = args.exr.empty() ? defaultOutput(args.scene) : args.exr;
    prepareOutputFile(exr);
    if (!args.png.empty()) prepareOutputFile(args.png);
    SceneDescription description = loadSceneDescription(args.scene);
    applyOverrides(args, description);
    RenderScene scene = buildRenderScene(description);
    Bvh bvh(scene);
    RenderStats stats;
    Film film = render(scene, bvh, RenderOptions{!args.quiet}, &stats);

    writeExr(film, exr);
    if (!args.png.empty()) writePng(film, args.png);
    if (stats.nonFiniteSamples) {
        std::fprintf(stderr, "veduta: warning: %llu samples were not finite and were dropped\n",
                     (unsigned long long)stats.nonFiniteSamples);
    }
    if (!args.quiet) {
        std::fprintf(stderr, "%s: %dx%d, %u spp, %.2f s, %.2f Mrays/s%s%s\n", exr.c_str(), film.width(), film.height(),
                     scene.settings.samplesPerPixel, stats.seconds, double(stats.rays.total()) / stats.seconds * 1e-6,
                     args.png.empty() ? "" : ", ", args.png.c_str());
    }
}

}  // namespace

void addRenderCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App *cmd = app.add_subcommand("render", "Path-trace a scene to OpenEXR (and optionally PNG)");
    cmd->add_option("scene", args->scene, "Scene file (XML); the built-in default scene when omitted")
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->exr, "EXR file to write [renders/<scene name>.exr]")
        ->check(CLI::Validator(checkExrName, "FILE.exr"));
    cmd->add_option("--png", args->png, "Also write an 8-bit sRGB PNG here")->check(CLI::Validator(checkPngName, "FILE.png"));
    cmd->add_option("--spp", args->spp, "Samples per pixel (overrides the scene)")->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--seed", args->seed, "Seed of every random choice (overrides the scene)");
    cmd->add_option("--max-depth", args->maxDepth, "Longest path, in bounces (overrides the scene)")
        ->check(CLI::Range(1u, 1024u));
    cmd->add_option("--tile", args->tileSize, "Tile size in pixels; changes speed, never the image")
        ->check(CLI::Range(1u, 4096u));
    cmd->add_option("--res", args->resolution, "Resolution WxH (overrides the scene)")
        ->check(CLI::Validator(checkResolution, "WxH"));
    cmd->add_option("--threads", args->threads, "Worker threads [all cores]")->check(CLI::Range(1u, 4096u));
    cmd->add_flag("-q,--quiet", args->quiet, "No progress bar and no summary");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runRender(*args); }); });
}

}  // namespace veduta
