#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "app/study_scene.h"
#include "assembly/build_scene.h"
#include "description/scene_description.h"
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

// What is exported: the scene file as `veduta render` reads it, or one building.
SceneDescription descriptionToExport(const ExportArgs &args) {
    if (args.building.rules.empty()) return loadSceneDescription(args.scene);
    return buildingScene(args.building, args.plan);
}

// The files the scene's maps were read from. Materials keep their names from the description
// into the scene, and the registry gives one file one id.
TextureFiles textureFiles(const SceneDescription &description, const RenderScene &scene) {
    std::map<std::string, const MaterialDesc *> byName;
    for (const MaterialDesc &d : description.materials) byName[d.material.name] = &d;
    TextureFiles out;
    auto add = [&](TextureId id, const ImageRef &ref) {
        if (id != kNoTexture && ref.given()) out.emplace(id, ref.file);
    };
    for (const Material &m : scene.materials) {
        auto found = byName.find(m.name);
        if (found == byName.end()) continue;
        const MaterialDesc &d = *found->second;
        add(m.diffuseMap, d.diffuseMap);
        add(m.specularMap, d.specularMap);
        add(m.normalMap, d.normalMap);
        add(m.reflectionMap, d.reflectionMap);
        add(m.opacityMap, d.opacityMap);
    }
    return out;
}

void runExport(const ExportArgs &args) {
    auto start = std::chrono::steady_clock::now();
    SceneDescription description = descriptionToExport(args);
    RenderScene scene = buildSceneWithWarnings(description);
    ExportOptions options;
    options.georeference = description.georeference;
    options.textureFiles = textureFiles(description, scene);
    options.progress = !args.quiet;
    // The option's check has accepted the extension.
    ExportStats stats = exportScene(scene, args.output, *exportFormatForPath(args.output), options);
    if (args.quiet) return;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "%s: %zu meshes, %zu instances, %zu triangles, %zu textures, %zu files, %.3f s\n",
                 args.output.c_str(), stats.meshes, stats.instances, stats.triangles, stats.textures, stats.files,
                 seconds);
    for (const auto &[reason, count] : stats.notes) std::fprintf(stderr, "  %zu %s\n", count, reason.c_str());
    if (!description.georeference) std::fprintf(stderr, "  no georeference: the file is in local metres only\n");
}

std::string checkExportFile(const std::string &text) {
    if (exportFormatForPath(text)) return {};
    return fmt::format("'{}' is not an .obj, .gltf, .glb or .ply file", text);
}

}  // namespace

void addExportCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App *cmd =
        app.add_subcommand("export",
                           "Write a scene's, or with --rules one building's, geometry and materials as glTF "
                           "(Y up, instanced, with camera, sun and textures), OBJ or PLY (Z up, instances "
                           "copied); georeferenced scenes get .prj and .geo.json sidecars");
    addSceneArgument(*cmd, args->scene);
    addStudyOptions(*cmd, args->building, true);
    addFootprintOptions(*cmd, args->plan, false);
    CLI::Option *rules = cmd->get_option("--rules");
    cmd->get_option("--footprint")->needs(rules);
    rules->needs("--footprint")->excludes("scene");
    cmd->add_option("-o,--output", args->output,
                    "glTF (with a .bin), GLB, OBJ (with an .mtl) or PLY file to write; maps' image files go beside it")
        ->required()
        ->check(CLI::Validator(checkExportFile, "FILE.gltf|.glb|.obj|.ply"));
    cmd->add_flag("-q,--quiet", args->quiet, "No progress line, no summary");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runExport(*args); }); });
}

}  // namespace veduta
