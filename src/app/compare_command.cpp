// `veduta compare A B`: two scenes of one place rendered with the same cameras, path-traced and
// previewed, their buildings paired and measured, and a report written (docs/compare.md).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "compare/building_comparison.h"
#include "compare/compare_report.h"
#include "compare/height_map.h"
#include "compare/image_metrics.h"
#include "compare/views.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "film/passes.h"
#include "io/output_files.h"
#include "io/xml_prolog.h"
#include "preview/preview.h"
#include "render/bvh.h"
#include "render/renderer.h"

namespace veduta {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Footprints are measured on at most this many cells: 0.5 m over a square kilometre.
constexpr size_t kMaxGridCells = 4'000'000;

struct CompareArgs {
    std::string a, b;
    std::string html, json;
    std::vector<std::string> cameras;  // each 'X Y Z LX LY LZ [FOV]'
    bool sceneCamera = false;
    unsigned views = 3;
    std::string resolution;  // empty: 960x540, or the scene camera's own
    std::optional<uint32_t> spp, maxDepth;
    unsigned threads = 0;
    bool quiet = false;
};

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

int64_t peakMemoryBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return int64_t(usage.ru_maxrss) * 1024;
}

// Whether the file is a CityGML model: its root element is a CityModel.
bool isCityGml(const fs::path &file) { return rootElementName(file).ends_with("CityModel"); }

// A CityGML file as a scene: the other scene's with its buildings replaced by the file's.
SceneDescription cityGmlScene(const fs::path &file, SceneDescription other) {
    other.source = file.string();
    other.buildingGroups.clear();
    other.cities.clear();
    other.cityGml.clear();
    CityGmlDesc desc;
    desc.loc = desc.fileLoc = desc.crsLoc = FileLoc{file.string()};
    desc.file = file;
    desc.objectId = 0xfffffff0u;  // an object id no scene's numbering reaches
    other.cityGml.push_back(desc);
    return other;
}

std::pair<SceneDescription, SceneDescription> loadPair(const CompareArgs &args) {
    bool gmlA = isCityGml(args.a), gmlB = isCityGml(args.b);
    if (gmlA && gmlB)
        throw InputError(FileLoc{args.b}, "both are CityGML files; one must be a scene (veduta twin makes one)");
    SceneDescription a = gmlA ? SceneDescription{} : loadSceneDescription(args.a);
    SceneDescription b = gmlB ? cityGmlScene(args.b, a) : loadSceneDescription(args.b);
    if (gmlA) a = cityGmlScene(args.a, b);
    for (SceneDescription *d : {&a, &b}) {
        if (args.spp) d->settings.samplesPerPixel = *args.spp;
        if (args.maxDepth) d->settings.maxDepth = *args.maxDepth;
    }
    return {std::move(a), std::move(b)};
}

Camera cameraOption(const std::string &text, const Camera &size) {
    std::vector<float> v;
    std::istringstream in(text);
    for (float x; in >> x;) v.push_back(x);
    if (!in.eof() || (v.size() != 6 && v.size() != 7) || (v[0] == v[3] && v[1] == v[4] && v[2] == v[5]) ||
        (v.size() == 7 && !(v[6] > 0 && v[6] < 180)))
        throw InputError(FileLoc{"--camera"},
                         fmt::format("'{}' is no camera: give 'X Y Z  LX LY LZ' (position, a different look-at point) "
                                     "and optionally the vertical field of view, degrees between 0 and 180",
                                     text));
    Camera camera = size;
    camera.position = {v[0], v[1], v[2]};
    camera.lookAt = {v[3], v[4], v[5]};
    if (v.size() > 6) camera.verticalFovDegrees = v[6];
    return camera;
}

std::vector<View> chooseViews(const CompareArgs &args, const RenderScene &a, const BuildingComparison &buildings,
                              const HeightMap &map) {
    Camera size;
    applyResolution(args.resolution.empty() ? "960x540" : args.resolution, size);
    std::vector<View> views;
    if (args.sceneCamera) {
        Camera camera = a.camera;
        if (!args.resolution.empty()) camera.width = size.width, camera.height = size.height;
        views.push_back({"the scene's camera", camera});
    }
    for (size_t i = 0; i < args.cameras.size(); ++i)
        views.push_back({fmt::format("camera {}", i + 1), cameraOption(args.cameras[i], size)});
    if (!views.empty() || args.views == 0) return views;
    float low = 1e30f, high = -1e30f;
    for (const BuildingPair &p : buildings.pairs)
        for (const auto *m : {&p.a, &p.b})
            if (*m && (*m)->record) low = std::min(low, (*m)->record->base), high = std::max(high, (*m)->record->ridge);
    if (low > high) low = 0, high = 10;
    views.push_back({"overview", overviewCamera(map.grid, low, high, size.width, size.height)});
    for (View &v : streetViews(buildings, map, args.views - 1, size.width, size.height)) views.push_back(std::move(v));
    return views;
}

// Renders every view of one scene, path-traced and previewed, into the results' A or B side.
void renderViews(RenderScene &scene, SceneCost &cost, std::vector<ViewResult> &results, bool sideA,
                 std::vector<std::vector<uint32_t>> &masks, bool quiet) {
    Bvh bvh(scene);
    cost.bvhBytes = bvh.stats().bytes, cost.bvhSeconds = bvh.stats().buildSeconds;
    cost.samplesPerPixel = scene.settings.samplesPerPixel;
    for (size_t i = 0; i < results.size(); ++i) {
        ViewResult &r = results[i];
        scene.camera = r.view.camera;
        if (!quiet)
            std::fprintf(stderr, "veduta: %s, view %zu of %zu (%s)\n", cost.name.c_str(), i + 1, results.size(),
                         r.view.name.c_str());
        RenderOptions options;
        options.showProgress = !quiet;
        RenderStats stats;
        Film film = makeFilm(scene, options);
        renderFilm(scene, bvh, options, film, stats);
        cost.renderSeconds += stats.seconds;
        LayeredImage image = developFilm(film);
        const LayeredImage::Channel *ids = image.find(passChannel("IndexBuilding", "X"));
        std::vector<uint32_t> mask(ids->values.size());
        for (size_t p = 0; p < mask.size(); ++p) mask[p] = uint32_t(ids->values[p]);
        masks[i] = std::move(mask);
        Clock::time_point start = Clock::now();
        PreviewImage preview = renderPreview(scene, PreviewOptions{});
        cost.previewSeconds += secondsSince(start);
        (sideA ? r.renderA : r.renderB) = combinedImage(image);
        (sideA ? r.previewA : r.previewB) = std::move(preview.film);
    }
}

void describeCost(const RenderScene &scene, SceneCost &cost) {
    for (const BakedMesh &m : scene.meshes) cost.storedTriangles += m.mesh.triangleCount();
    for (const Mesh &m : scene.prototypes) cost.storedTriangles += m.triangleCount();
    cost.effectiveTriangles = scene.effectiveTriangleCount();
    cost.instances = scene.instances.size();
    cost.buildings = scene.buildings.size();
    cost.effort = scene.effort;
}

RenderScene buildTimed(const SceneDescription &description, SceneCost &cost) {
    Clock::time_point start = Clock::now();
    RenderScene scene = buildSceneWithWarnings(description);
    cost.generateSeconds = secondsSince(start);
    describeCost(scene, cost);
    return scene;
}

void printHeadline(const CompareReport &r, const fs::path &html, const fs::path &json) {
    const BuildingComparison &c = r.buildings;
    std::printf("buildings: %zu paired by id, %zu by overlap, %zu only in A, %zu only in B\n", c.matchedById,
                c.matchedByOverlap, c.onlyA, c.onlyB);
    std::printf(
        "mean footprint IoU %.4f, mean |eaves error| %.3f m, mean |ridge error| %.3f m, "
        "mean |volume error| %.2f %%, roof types agreeing %.1f %%\n",
        c.meanFootprintIou, c.meanAbsEavesError, c.meanAbsRidgeError, c.meanAbsVolumeError * 100,
        c.roofAgreement * 100);
    for (const ViewResult &v : r.views)
        std::printf("%s: relMSE %.4g, PSNR %.2f dB, SSIM %.4f, silhouette IoU %.4f\n", v.view.name.c_str(),
                    v.rendered.relMse, v.rendered.psnr, v.rendered.ssim, v.silhouetteIou);
    std::printf("wrote %s and %s\n", html.c_str(), json.c_str());
}

void runCompare(const CompareArgs &args) {
    auto threadLimit = limitThreads(args.threads);
    fs::path html = args.html.empty() ? fs::path("renders/compare.html") : fs::path(args.html);
    fs::path json = args.json.empty() ? fs::path(html).replace_extension(".json") : fs::path(args.json);
    prepareOutputFile(html);
    prepareOutputFile(json);
    Camera size;
    for (const std::string &c : args.cameras) cameraOption(c, size);  // checked before the long work
    auto [descA, descB] = loadPair(args);

    CompareReport report;
    report.a.name = args.a, report.b.name = args.b;
    RenderScene a = buildTimed(descA, report.a);
    RenderScene b = buildTimed(descB, report.b);
    GroundGrid grid = gridOverBuildings(a, b, kMaxGridCells);
    report.mapA = topDownHeights(a, grid);
    report.mapB = topDownHeights(b, grid);
    report.buildings = compareBuildings(a, report.mapA, b, report.mapB);
    if (a.buildings.empty() && b.buildings.empty())
        std::fprintf(
            stderr,
            "veduta: warning: neither scene has buildings a generator recorded; only the images are compared\n");

    std::vector<View> views = chooseViews(args, a, report.buildings, report.mapA);
    if (views.empty()) throw InputError(FileLoc{"--views"}, "no view to render");
    for (View &v : views) {
        ViewResult result;
        result.view = std::move(v);
        report.views.push_back(std::move(result));
    }
    std::vector<std::vector<uint32_t>> masksA(views.size()), masksB(views.size());
    renderViews(a, report.a, report.views, true, masksA, args.quiet);
    report.a.peakMemoryBytes = peakMemoryBytes();
    a = RenderScene{};
    renderViews(b, report.b, report.views, false, masksB, args.quiet);
    report.b.peakMemoryBytes = peakMemoryBytes();
    for (size_t i = 0; i < views.size(); ++i) {
        ViewResult &r = report.views[i];
        r.rendered = compareRenderings(r.renderA, r.renderB);
        r.previewed = compareRenderings(r.previewA, r.previewB);
        r.silhouetteIou = silhouetteIou(masksA[i], masksB[i]);
    }

    std::string page = reportHtml(report), figures = reportJson(report);
    OutputSet outputs({html, json});
    writeBytesAtomically(html, page.data(), page.size());
    writeBytesAtomically(json, figures.data(), figures.size());
    outputs.commit();
    printHeadline(report, html, json);
}

}  // namespace

void addCompareCommand(CLI::App &app, int &exitCode) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App *cmd = app.add_subcommand(
        "compare", "Render two scenes of one place with the same cameras and report how they differ (HTML and JSON)");
    cmd->add_option("A", args->a, "The reference: a scene file, or a CityGML file (placed in B's scene)")->required();
    cmd->add_option("B", args->b, "The scene compared with it (or a CityGML file, placed in A's scene)")->required();
    cmd->add_option("-o,--output", args->html, "HTML report to write [renders/compare.html]")
        ->check(fileWithExtension(".html"));
    cmd->add_option("--json", args->json, "JSON file of every figure [the report's name with .json]")
        ->check(fileWithExtension(".json"));
    cmd->add_option("--camera", args->cameras,
                    "A view: position and look-at point, and optionally the vertical field of view (repeatable); "
                    "replaces the automatic views")
        ->type_name("'X Y Z LX LY LZ [FOV]'");
    cmd->add_flag("--scene-camera", args->sceneCamera, "Render A's own camera (instead of the automatic views)");
    cmd->add_option(
           "--views", args->views,
           "Automatic views: an overview and street-level views of buildings spread over A, this many in all [3]")
        ->check(CLI::Range(1u, 100u));
    addResolutionOption(*cmd, args->resolution);
    cmd->add_option("--spp,--samples", args->spp, "Samples per pixel of the path-traced views [the scenes']")
        ->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--max-depth", args->maxDepth, "Longest path, in bounces [the scenes']")
        ->check(CLI::Range(1u, 1024u));
    addThreadsOption(*cmd, args->threads);
    cmd->add_flag("-q,--quiet", args->quiet, "No progress output");
    cmd->callback([args, &exitCode] { exitCode = runGuarded([&] { runCompare(*args); }); });
}

}  // namespace veduta
