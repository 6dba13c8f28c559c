// The cameras `veduta compare` renders both scenes with when the command line names none
// (docs/compare.md): an overview of the district and street-level views of some of its buildings.
#pragma once

#include <string>
#include <vector>

#include "compare/building_comparison.h"
#include "compare/height_map.h"
#include "scene/camera.h"

namespace veduta {

struct View {
    std::string name;  // "overview", "building 123", "camera 2", "scene"
    Camera camera;
};

// Looking down on the whole grid from the south-south-west at 35°, far enough for its
// buildings (up to `top` high, from `ground`) to fit the picture.
Camera overviewCamera(const GroundGrid &grid, float ground, float top, int width, int height);

// Up to `count` views from eye height in front of buildings spread over the reference
// scene's (every n-th by id): each from a free cell of the map (no building there) about
// 12 m in front of the building, looking at its middle.
std::vector<View> streetViews(const BuildingComparison &buildings, const HeightMap &map, size_t count, int width,
                              int height);

}  // namespace veduta
