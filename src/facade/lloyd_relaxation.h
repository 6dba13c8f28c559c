// Lloyd relaxation of seed points inside a wall face (digest-001 §2.5, L1095, after Hiller et al.
// [HHD03]): the Voronoi diagram of the seeds, each cell clipped to the wall minus its openings, each
// free seed moved to its clipped cell's centroid, until the largest move falls under a threshold or
// the steps run out. Stopping early leaves the cells irregular, converging makes them regular
// (L1095); cyclopean masonry (facade/cyclopean.h) takes the clipped cells as its stones.
//
// WallRegion, the wall minus its openings, lives here because clipping to it is the step Lloyd
// repeats. Every clipped cell is one or more pieces (an opening may cut a cell in two); a piece's
// outline runs counter-clockwise and its holes clockwise, so that signed areas add up.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "core/vecmath.h"
#include "facade/masonry.h"

namespace veduta {

// A connected part of a region: its outline counter-clockwise, its holes clockwise.
struct RegionPiece {
    std::vector<Vec2d> outline;
    std::vector<std::vector<Vec2d>> holes;
};

// The part of one Voronoi cell inside the wall: empty, one piece, or several.
using ClippedCell = std::vector<RegionPiece>;

// The wall face minus its openings, held exactly (CGAL's exact kernel) for the Boolean operations.
class WallRegion {
  public:
    // The outline and openings must be simple polygons (either orientation).
    explicit WallRegion(const WallFace &wall);
    ~WallRegion();
    WallRegion(WallRegion &&) noexcept;
    WallRegion &operator=(WallRegion &&) noexcept;

    const std::vector<RegionPiece> &pieces() const;
    double area() const;
    Vec2d lower() const;  // the corners of the bounding rectangle
    Vec2d upper() const;
    bool contains(Vec2d point) const;  // strictly inside: not on the boundary
    // The part of a convex, counter-clockwise polygon that lies in the region.
    ClippedCell clip(const std::vector<Vec2d> &convexPolygon) const;
    // The area, centroid and ∫|x − origin|² dA of that part, without Boolean operations: what
    // each Lloyd step needs, at a fraction of the cost.
    struct Moments {
        double area = 0;
        Vec2d centroid;  // when area > 0
        double secondMoment = 0;
    };
    Moments moments(const std::vector<Vec2d> &convexPolygon, Vec2d origin) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The part of a polygon where dot(x, normal) <= offset (one Sutherland–Hodgman step): the Voronoi
// cells are cut from a box this way, and stones shrunk by their joints. The result has no repeated
// or collinear vertices (within a nanometre), and is empty when no area is left. A convex polygon
// stays one; a concave one may come back as parts joined along the line, which still has the
// right signed area and moments.
std::vector<Vec2d> clipToHalfPlane(const std::vector<Vec2d> &polygon, Vec2d normal, double offset);

// The area of a piece or a whole cell (holes subtracted).
double area(const RegionPiece &piece);
double area(const ClippedCell &cell);

// The Voronoi cell of every seed, clipped to the region, in the order of the seeds. Of seeds at
// one place only one gets a cell; the others get an empty one.
std::vector<ClippedCell> clippedVoronoiCells(const WallRegion &region, const std::vector<Vec2d> &seeds);

struct LloydSettings {
    int maxIterations = 0;      // `Lloyd` (Def A.16)
    double shiftThreshold = 0;  // metres: stop once no free seed moves this far
};

struct LloydResult {
    std::vector<Vec2d> seeds;        // the fixed seeds first, unmoved, then the relaxed ones
    std::vector<ClippedCell> cells;  // the clipped Voronoi cell of each final seed (exact Booleans)
    std::vector<double> meanShifts;  // per step: how far the free seeds moved on average, metres
    // Per Voronoi diagram computed (one more than the steps, the last for the final seeds): the
    // sum over cells of ∫|x − seed|² dA, which Lloyd never increases (the record a test can rely
    // on; the mean shift usually falls too, but need not).
    std::vector<double> energies;
};

// Relaxes `seeds` in `region`; the first `fixedCount` seeds stay where they are (the corner seeds
// of Fig. 5.15). A seed whose cell is empty stays too.
LloydResult relaxLloyd(const WallRegion &region, std::vector<Vec2d> seeds, size_t fixedCount,
                       const LloydSettings &settings);

}  // namespace veduta
