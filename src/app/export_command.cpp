#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "app/study_scene.h"
#include "assembly/build_scene.h"
#include "io/scene_export.h"

namespace veduta {

namespace {

struct ExportArgs {
    std::string scene;
    StudyOptions building;  // with --rules: one building instead of a scene
    BuildingOptions plan;
    std::string output;
    bool quiet = false;
};

// What is exported: the scene file built as `veduta render` builds it, or one building.
RenderScene sceneToExport(const ExportArgs &args) {
    if (args.building.rules.empty()) return buildSceneWithWarnings(loadSceneDescription(args.scene));
    return buildSceneWithWarnings(buildingScene(args.building, args.plan));
}

void runExport(const ExportArgs &args) {
    auto start = std::chrono::steady_clock::now();
    RenderScene scene = sceneToExport(args);
    // The option's check has accepted the extension.
    ExportStats stats = exportScene(scene, args.output, *exportFormatForPath(args.output));
    if (!args.quiet) {
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "%s: %zu meshes, %zu instances, %zu triangles, %zu files, %.3f s\n", args.output.c_str(),
                     stats.meshes, stats.instances, stats.triangles, stats.files, seconds);
    }
}

std::string checkExportFile(const std::string &text) {
    if (exportFormatForPath(text)) return {};
    return fmt::format("'{}' is not an .obj, .gltf or .glb file", text);
}

}  // namespace

void addExportCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App *cmd = app.add_subcommand("export",
                                       "Write a scene's, or with --rules one building's, geometry and materials as OBJ "
                                       "(Z up, instances copied) or glTF (Y up, instanced)");
    addSceneArgument(*cmd, args->scene);
    addStudyOptions(*cmd, args->building, true);
    addFootprintOptions(*cmd, args->plan, false);
    CLI::Option *rules = cmd->get_option("--rules");
    cmd->get_option("--footprint")->needs(rules);
    rules->needs("--footprint")->excludes("scene");
    cmd->add_option("-o,--output", args->output, "OBJ (with an .mtl), glTF (with a .bin) or GLB file to write")
        ->required()
        ->check(CLI::Validator(checkExportFile, "FILE.obj|.gltf|.glb"));
    cmd->add_flag("-q,--quiet", args->quiet, "No summary line");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runExport(*args); }); });
}

}  // namespace veduta
