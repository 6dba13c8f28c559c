// Queries over the finished terrain mesh (drapeAreas' mesh after the water is levelled): the
// height at a point and the exact extremes over a polygon, for buildings (minOver their
// footprint) and ribbons (never below the surface). A uniform bucket grid finds the triangles.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "geo/grid_lines.h"
#include "scene/mesh.h"

namespace veduta {

// z = a + b·x + c·y
struct HeightPlane {
    double a = 0, b = 0, c = 0;

    double at(Vec2d p) const { return a + b * p.x + c * p.y; }
};

class TerrainSurface {
  public:
    // `terrain` in local coordinates, its xy a height field (no overlapping triangles).
    // `cellLines`, the DGM's lines (gridLines), size the buckets and are where ribbons cut
    // their centre lines; without them (empty) the buckets are sized from the mesh.
    TerrainSurface(const Mesh &terrain, GridLines cellLines);

    // The surface's height at p, or nullopt off the mesh. A point on an edge or vertex reads
    // any triangle holding it (they agree there up to rounding).
    std::optional<double> heightAt(Vec2d p) const;
    // The triangle (an index into the mesh's triangles) under p and the height there, or
    // nullopt off the mesh; on a shared edge, the triangle p lies deepest in.
    struct PointOnSurface {
        uint32_t triangle = 0;
        double height = 0;
    };
    std::optional<PointOnSurface> triangleAt(Vec2d p) const;
    // The highest and lowest point of the surface over a simple polygon (either winding),
    // boundary included, or nullopt where the polygon misses the mesh. Exact for the
    // piecewise-linear surface up to double rounding: the extreme is at a polygon corner, a
    // mesh vertex inside, or where a mesh edge crosses the polygon's boundary.
    std::optional<double> maxOver(std::span<const Vec2d> polygon) const;
    std::optional<double> minOver(std::span<const Vec2d> polygon) const;
    std::optional<double> maxOver(std::span<const Vec2f> polygon) const;
    std::optional<double> minOver(std::span<const Vec2f> polygon) const;
    // The maximum of surface − plane over the polygon: how far a planar piece with that plane
    // would have to rise to lie nowhere below the surface.
    std::optional<double> maxAbove(std::span<const Vec2d> polygon, const HeightPlane &plane) const;

    const GridLines &cellLines() const { return lines_; }

  private:
    std::optional<double> extreme(std::span<const Vec2d> polygon, const HeightPlane &plane, double sign) const;
    std::vector<uint32_t> trianglesNear(double x0, double y0, double x1, double y1) const;
    int bucketColumn(double x) const;
    int bucketRow(double y) const;

    std::vector<Vec3f> positions_;
    std::vector<uint32_t> indices_;
    GridLines lines_;
    double originX_ = 0, originY_ = 0, bucketSize_ = 1;
    int bucketColumns_ = 0, bucketRows_ = 0;
    std::vector<uint32_t> bucketStart_;  // CSR: the triangles of bucket k are bucketTriangles_[start[k], start[k + 1])
    std::vector<uint32_t> bucketTriangles_;
};

}  // namespace veduta
