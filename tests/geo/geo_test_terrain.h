// Synthetic terrains and mesh checks shared by the draping, surface and ribbon tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geo/drape_areas.h"
#include "geo/grid_lines.h"
#include "geo/height_grid.h"
#include "geo/terrain_surface.h"
#include "geodesy/local_frame.h"
#include "scene/mesh.h"

namespace veduta::test {

// A deterministic number in [0, 1) from a seed and an index.
double unitRandom(uint32_t seed, uint32_t index);

HeightGrid flatTerrain(int columns, int rows, double spacing, MapPoint southWest, float height);

// A DGM draped in `frame` with `areas` (none: the bare terrain), and the surface of that mesh.
struct DrapedDgm {
    HeightGrid grid;
    Mesh mesh;
    TerrainSurface surface;

    DrapedDgm(HeightGrid g, const LocalFrame &frame, const std::vector<DrapeArea> &areas = {}) :
        grid(std::move(g)), mesh(drapeAreas(grid, frame, areas, {}).mesh), surface(mesh, gridLines(grid, frame)) {}
};
// Rough: smooth value noise of 40 m, a slope of 0.8 eastwards, a sharp ridge 30 m high
// running east–west through the middle and ±1.5 m of noise at every node.
HeightGrid roughTerrain(int columns, int rows, double spacing, MapPoint southWest, uint32_t seed);

// The grid's piecewise-linear surface at p (SW–NE diagonals), written independently of the
// library; NaN off the grid or in a cell without data.
double gridSurface(const HeightGrid &grid, MapPoint p);

// Problems of a terrain mesh as text, empty when none: an edge not used exactly twice in
// opposite directions unless it lies on the rectangle [x0, x1] × [y0, y1] (the grid's
// boundary, local); a triangle facing down or of zero plan area.
std::vector<std::string> meshDefects(const Mesh &mesh, double x0, double y0, double x1, double y1);

double planArea(const Mesh &mesh, size_t triangle);  // signed, counter-clockwise positive
Vec2d planCentroid(const Mesh &mesh, size_t triangle);
double ringArea(const std::vector<Vec2d> &ring);           // absolute
bool insideRing(const std::vector<Vec2d> &ring, Vec2d p);  // even–odd

}  // namespace veduta::test
