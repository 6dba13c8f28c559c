// Footprints into floor-plan modules (digest-001 §9): a simple polygon as the city data give it
// (CityData, OSM, ATKIS, CityGML; either orientation, repeated or collinear points) is split
// into convex modules by CGAL's convex partition and joined by KK docks on the shared edges,
// with the largest piece as the dominant root. The plan's features then trace the footprint.
//
// Choices:
// * Footprints of up to kOptimalPartitionMaxVertices vertices (after cleaning) get CGAL's
//   optimal_convex_partition_2 (Greene, fewest pieces, O(n^4) in the worst case); larger ones
//   approx_convex_partition_2 (Hertel-Mehlhorn, at most four times the fewest pieces, O(n)).
//   Measured (g++ -O2, this project's build machine, 2026-12): a star with every other vertex
//   reflex, the worst case, takes 11 ms optimal at 32 vertices, 56 ms at 48, 200 ms at 64 and
//   5.8 s at 128 (approx: under 2 ms); comb-shaped blocks of 34/98 vertices take 0.7/4.7 ms.
//   32 keeps the worst single footprint near 10 ms, so a town of thousands stays interactive.
// * Repeated and collinear points are removed first: a collinear vertex would otherwise end
//   up in one piece and not its neighbour, and the shared edge would not match.
// * Each piece is docked onto its neighbour nearer the root by the whole shared edge (a = 0,
//   b = 1); the pieces keep the footprint's exact coordinates.
#pragma once

#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/floor_plan.h"

namespace veduta {

inline constexpr size_t kOptimalPartitionMaxVertices = 32;

// The footprint without repeated points and collinear vertices, counter-clockwise. Throws
// InputError at `loc` when fewer than three vertices remain or the outline crosses itself.
std::vector<Vec2d> cleanFootprint(const std::vector<Vec2d> &footprint, const FileLoc &loc);

// The footprint as a floor plan of convex modules; each module copies type, wall thickness,
// height and material from `prototype` (whose outline is not used).
FloorPlan partitionFootprint(const std::vector<Vec2d> &footprint, const FloorPlanModule &prototype, const FileLoc &loc);

}  // namespace veduta
