// A draped ribbon (geo/ribbons.h) read back from its mesh's layout: per cross-section a left and a
// right vertex at one height, a piece of two triangles between neighbouring cross-sections. What
// is laid on a ribbon (road markings, a track's sleepers and rails) is placed through it: by
// distance along the centre line and offset across it, at the height of the ribbon's own
// triangles.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "core/vecmath.h"
#include "scene/mesh.h"

namespace veduta {

class RibbonFrame {
  public:
    // Keeps a reference to `mesh`, which must outlive it. A mesh not in drapeRibbon's layout
    // gives a frame of no stations.
    explicit RibbonFrame(const Mesh &mesh);

    size_t stations() const { return centre_.size(); }
    double length() const { return along_.empty() ? 0 : along_.back(); }
    double along(size_t i) const { return along_[i]; }
    Vec2d centre(size_t i) const { return centre_[i]; }

    // Whether p lies within `reach` of the centre line's bounding box: a cheap test before an
    // exact distance.
    bool near(Vec2d p, double reach) const;

    // The point of piece i at fraction t along it and k half widths left of the centre. The
    // miters keep k's perpendicular distance from both pieces at a corner.
    Vec2d at(size_t i, double t, double k) const;
    // The piece and fraction at distance s along the centre line.
    std::pair<size_t, double> pieceAt(double s) const;
    // Where the line k half widths left of the centre crosses piece i's diagonal (right corner at
    // i to left corner at i + 1), as a fraction of the piece, if inside it.
    std::optional<double> diagonalCrossing(size_t i, double k) const;
    // The height of piece i's surface at p: the plane of whichever of its two triangles holds p
    // (the one it lies least outside of, against rounding).
    double heightAt(size_t i, Vec2d p) const;

  private:
    Vec2d plan(size_t v) const { return {mesh_.positions[v].x, mesh_.positions[v].y}; }

    const Mesh &mesh_;
    std::vector<Vec2d> centre_, across_;
    std::vector<double> along_;
    Vec2d low_, high_;
};

}  // namespace veduta
