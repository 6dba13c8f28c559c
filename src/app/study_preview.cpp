#include "app/study_preview.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/command_options.h"
#include "app/scene_loading.h"
#include "io/output_files.h"
#include "preview/preview.h"

namespace veduta {

void addStudyPreviewOptions(CLI::App &command, StudyPreviewOptions &options, const std::string &defaultName) {
    command
        .add_option("-o,--output", options.output, "PNG (sRGB) or EXR (linear) to write [renders/" + defaultName + "]")
        ->check(fileWithExtension(".png") | fileWithExtension(".exr"));
    addResolutionOption(command, options.resolution);
    command.add_flag("--no-shadows", options.noShadows, "Leave out the sun's shadows");
    command.add_flag("-q,--quiet", options.quiet, "No summary line");
}

void previewStudy(SceneDescription scene, const StudyPreviewOptions &options, const std::string &defaultName) {
    auto start = std::chrono::steady_clock::now();
    std::string output = options.output.empty() ? "renders/" + defaultName : options.output;
    prepareOutputFile(output);
    applyResolution(options.resolution, scene.camera);
    RenderScene built = buildSceneWithWarnings(scene);
    PreviewOptions preview;
    preview.shadows = !options.noShadows;
    PreviewImage image = renderPreview(built, preview);
    if (std::filesystem::path(output).extension() == ".exr") writeExr(image.film, output);
    else writePng(image.film, output);
    if (options.quiet) return;
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "%s: %dx%d, %zu instances, %llu triangles, %.3f s\n", output.c_str(), image.film.width(),
                 image.film.height(), built.instances.size(),
                 static_cast<unsigned long long>(built.effectiveTriangleCount()), seconds);
}

}  // namespace veduta
