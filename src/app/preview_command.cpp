#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "io/output_files.h"
#include "preview/preview.h"

namespace veduta {

namespace {

struct PreviewArgs {
    std::string scene;
    std::string output;
    PreviewMode mode = PreviewMode::Shaded;
    std::string resolution;
    unsigned threads = 0;
    bool wireframe = false;
    bool cull = false;
    bool shadows = false;
    bool quiet = false;
};

void runPreview(const PreviewArgs &args) {
    auto start = std::chrono::steady_clock::now();
    auto threadLimit = limitThreads(args.threads);
    std::string output = args.output.empty() ? defaultOutput(args.scene, "-preview.png") : args.output;
    prepareOutputFile(output);
    SceneDescription description = loadSceneDescription(args.scene);
    applyResolution(args.resolution, description.camera);
    RenderScene scene = buildSceneWithWarnings(description);

    PreviewOptions options;
    options.mode = args.mode;
    options.wireframe = args.wireframe;
    options.backfaceCulling = args.cull;
    options.shadows = args.shadows;
    PreviewImage image = renderPreview(scene, options);
    if (std::filesystem::path(output).extension() == ".exr") {
        writeExr(image.film, output);
    } else {
        writePng(image.film, output);
    }
    if (!args.quiet) {
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "%s: %dx%d preview, %.3f s\n", output.c_str(), image.film.width(), image.film.height(),
                     seconds);
    }
}

}  // namespace

void addPreviewCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<PreviewArgs>();
    CLI::App *cmd = app.add_subcommand("preview", "Rasterize a scene quickly with the render camera, to PNG (or EXR)");
    addSceneArgument(*cmd, args->scene);
    cmd->add_option("-o,--output", args->output,
                    "PNG (sRGB) or EXR (linear) to write [renders/<scene name>-preview.png]")
        ->check(fileWithExtension(".png") | fileWithExtension(".exr"));
    const std::map<std::string, PreviewMode> modes = {{"shaded", PreviewMode::Shaded}, {"albedo", PreviewMode::Albedo},
                                                      {"normal", PreviewMode::Normal}, {"depth", PreviewMode::Depth},
                                                      {"id", PreviewMode::Id},         {"thesis", PreviewMode::Thesis}};
    cmd->add_option("--mode", args->mode,
                    "What to show: shaded, albedo, normal, depth, id or thesis (seed 000's PPSUNS shader) [shaded]")
        ->transform(CLI::CheckedTransformer(modes, CLI::ignore_case));
    addResolutionOption(*cmd, args->resolution);
    addThreadsOption(*cmd, args->threads);
    cmd->add_flag("--wireframe", args->wireframe, "Draw triangle edges over the image");
    cmd->add_flag("--cull", args->cull, "Skip triangles facing away from the camera");
    cmd->add_flag("--shadows", args->shadows, "Sun shadows from a 2048x2048 shadow map (shaded mode)");
    cmd->add_flag("-q,--quiet", args->quiet, "No summary line");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runPreview(*args); }); });
}

}  // namespace veduta
