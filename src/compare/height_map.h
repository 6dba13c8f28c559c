// A district seen from straight above: for each cell of a grid over the ground, the height of
// the highest surface there and the building it belongs to. `veduta compare` measures
// footprints and volumes on it, the same way for a modelled district and a procedural one.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/render_scene.h"

namespace veduta {

struct GroundGrid {
    double x0 = 0, y0 = 0;  // the south-west corner, scene metres
    double cell = 1;        // metres on a side
    int width = 0, height = 0;

    size_t cellCount() const { return size_t(width) * size_t(height); }
};

struct HeightMap {
    GroundGrid grid;
    std::vector<float> top;          // the highest surface over each cell's centre; −infinity: none
    std::vector<uint32_t> building;  // its building id; 0: no building (ground, trees, nothing)
    // The building whose recorded ground plan (BuildingRecord::footprint) holds the cell's
    // centre; 0: none. Unlike `building`, roof overhangs are not in it.
    std::vector<uint32_t> plan;
};

// A grid of at most `maxCells` cells, the finest of 1 cm steps no finer than 10 cm, over the
// buildings of both scenes (their records' heights aside, their triangles' extent) and a margin
// of 2 m. An empty grid when neither has a building.
GroundGrid gridOverBuildings(const RenderScene &a, const RenderScene &b, size_t maxCells);

// Every triangle of the scene (baked and instanced) drawn from above onto the grid, the
// highest one winning each cell's centre; upright triangles cover no centre. The plan is
// drawn from the scene's building records.
HeightMap topDownHeights(const RenderScene &scene, const GroundGrid &grid);

}  // namespace veduta
