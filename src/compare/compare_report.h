// The report of `veduta compare` (docs/compare.md): one self-contained HTML page (its images
// inside it as data URIs, so it opens from disk without a server) and a JSON file of every
// figure in it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "compare/building_comparison.h"
#include "compare/height_map.h"
#include "compare/image_metrics.h"
#include "compare/views.h"
#include "core/rgba_image.h"
#include "scene/render_scene.h"

namespace veduta {

struct ViewResult {
    View view;
    RgbaImage renderA{0, 0}, renderB{0, 0};    // path-traced, linear
    RgbaImage previewA{0, 0}, previewB{0, 0};  // the preview rasterizer's, linear
    ImageMetrics rendered, previewed;
    double silhouetteIou = 1;  // of the building pixels (IndexBuilding pass) of the two renders
};

// What a scene costs to store, build and render.
struct SceneCost {
    std::string name;  // as the command line gave it
    uint64_t storedTriangles = 0, effectiveTriangles = 0, instances = 0, buildings = 0;
    int64_t bvhBytes = 0;
    double generateSeconds = 0, bvhSeconds = 0, renderSeconds = 0, previewSeconds = 0;
    int64_t peakMemoryBytes = 0;  // the process's peak resident size once this scene was done
    ModelEffort effort;
    uint32_t samplesPerPixel = 0;
};

struct CompareReport {
    SceneCost a, b;
    std::vector<ViewResult> views;
    BuildingComparison buildings;
    HeightMap mapA, mapB;
};

// A picture of the district from above, each building coloured by its footprint IoU with its
// partner (green 1, through yellow, to red 0; magenta where the other scene has none; B's
// alone darker), at most `maxSide` pixels on its longer side, north up.
RgbaImage districtErrorMap(const CompareReport &report, int maxSide);

std::string reportJson(const CompareReport &report);
std::string reportHtml(const CompareReport &report);

}  // namespace veduta
