#include <cstdio>
#include <memory>
#include <string>
#include <unordered_set>

#include <sys/resource.h>

#include "app/command_options.h"
#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "assembly/build_scene.h"
#include "render/bvh.h"

namespace veduta {

namespace {

void runInfo(const std::string &path) {
    RenderScene scene = buildSceneWithWarnings(loadSceneDescription(path));
    uint64_t stored = 0;
    for (const BakedMesh &m : scene.meshes) stored += m.mesh.triangleCount();
    for (const Mesh &p : scene.prototypes) stored += p.triangleCount();
    // Every generator (buildings, cities, CityGML) gives each building an id of its own, except
    // to the distant ones merged into a mesh with others, which it counts.
    std::unordered_set<uint32_t> buildings;
    uint64_t merged = 0;
    for (const auto &[level, counts] : scene.lods) merged += counts.merged;
    for (const BakedMesh &m : scene.meshes)
        if (m.buildingId != 0) buildings.insert(m.buildingId);
    for (const Instance &i : scene.instances)
        if (i.buildingId != 0) buildings.insert(i.buildingId);
    Bvh bvh(scene);

    std::printf("scene: %s\n", path.empty() ? "<built-in default scene>" : path.c_str());
    std::printf("resolution: %dx%d\n", scene.camera.width, scene.camera.height);
    std::printf("spp: %u\n", scene.settings.samplesPerPixel);
    std::printf("materials: %zu\n", scene.materials.size());
    std::printf("meshes: %zu\n", scene.meshes.size());
    std::printf("prototypes: %zu\n", scene.prototypes.size());
    std::printf("instances: %zu\n", scene.instances.size());
    std::printf("buildings: %llu\n", (unsigned long long)(buildings.size() + merged));
    for (const auto &[level, counts] : scene.lods)
        std::printf("lod %s: %llu buildings, %llu triangles, %llu meshes, %llu instances\n", level.c_str(),
                    (unsigned long long)counts.buildings, (unsigned long long)counts.triangles,
                    (unsigned long long)counts.meshes, (unsigned long long)counts.instances);
    // Eq 1 against Table 2's caps, reported and not judged (docs/slg.md).
    for (const auto &[zone, d] : scene.densities)
        std::printf("density %s: %llu lots, GRZ %.2f (cap %.2f), GFZ %.2f (cap %.2f)\n", zone.c_str(),
                    (unsigned long long)d.lots, d.footprintArea / d.lotArea, d.grzCap, d.floorArea / d.lotArea,
                    d.gfzCap);
    std::printf("stored_triangles: %llu\n", (unsigned long long)stored);
    std::printf("effective_triangles: %llu\n", (unsigned long long)scene.effectiveTriangleCount());
    std::printf("bvh_build_seconds: %.3f\n", bvh.stats().buildSeconds);
    std::printf("bvh_bytes: %lld\n", (long long)bvh.stats().bytes);
    std::printf("bvh_peak_bytes: %lld\n", (long long)bvh.stats().peakBytes);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("peak_rss_bytes: %lld\n", (long long)usage.ru_maxrss * 1024);
}

}  // namespace

void addInfoCommand(CLI::App &app, int &exitCode) {
    auto path = std::make_shared<std::string>();
    CLI::App *cmd = app.add_subcommand("info", "Build a scene's geometry and BVH and print key: value statistics");
    addSceneArgument(*cmd, *path);
    cmd->callback([path, &exitCode] { exitCode = runGuarded([&] { runInfo(*path); }); });
}

}  // namespace veduta
