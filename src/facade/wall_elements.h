// A storey's facade split into its elements: base walls, house corners, walls and inter-wall
// elements (Zwischenwandelemente, ZWE), and the horizontal partitions on them that line up into
// facade-wide bands (Finkenzeller 2008, Defs 5.1–5.4, L996–1010; digest-001 §2.4).
//
// Input is the storey's outline as feature polylines, counter-clockwise seen from above, in
// metres (the thesis walks clockwise; only the convexity test depends on it, so we keep the
// project's counter-clockwise convention). Consecutive features share their joint point.
//
// Choices where the thesis is open:
// * Closing: when the outline is closed and the last point differs from the first, the closing
//   edge belongs to the last feature, so one closed feature can be a whole polygon without
//   repeating its first point (Def 4.1: (p_n, p_1) ∈ E).
// * Corners (Def 5.2) stand at every joint of two base walls that turns left (convex for a
//   counter-clockwise outline); concave and straight joints get none, nor do the free ends of
//   an open outline. The thesis can take inner feature points as convex because its modules are
//   convex; a footprint outline need not be, so every joint is tested.
// * A corner is h_Hausecken wide on each of its two walls and taken off them; on a wall shorter
//   than three corner widths each corner face shrinks to a third of it, so that a wall remains.
// * Count rule (digest [GAP]; `Unterteilung` stores h_ZWE and an aspect ratio): with free length
//   L, ZWE width z and target wall width w = ratio · z, the count is n = round((L + z) / (w + z))
//   walls (at least 1) and n − 1 ZWE; the walls share what the ZWE leave equally. So a long wall
//   gets evenly spaced piers of the given width, and the ratio keeps its rhythm.
// * A corner appears as two elements, one face on each base wall, so that elements follow the
//   outline and a band runs through corners as one piece.
#pragma once

#include <cstddef>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

// h_Hausecken, h_ZWE and the wall-to-ZWE width ratio of the `Unterteilung` concept (L1517),
// in metres and a plain ratio.
struct WallSubdivision {
    double cornerWidth = 0;
    double interWallWidth = 0;  // 0: no ZWE, one wall per base wall
    double wallToInterWallRatio = 4;
};

// An edge of a feature (Def 5.1).
struct BaseWall {
    Vec2d start, end;
    size_t feature = 0;
    double length() const { return veduta::length(end - start); }
};

enum class ElementKind { CornerFace, Wall, InterWall };

// A piece of a base wall from `from` to `to` metres along it.
struct FacadeElement {
    ElementKind kind = ElementKind::Wall;
    size_t baseWall = 0;
    double from = 0, to = 0;
    size_t corner = 0;  // for a CornerFace: the corner it belongs to
};

// A house corner (Def 5.2) between base walls `before` and `after`.
struct HouseCorner {
    Vec2d point;
    size_t before = 0, after = 0;
};

struct StoreyFacade {
    std::vector<BaseWall> baseWalls;
    std::vector<HouseCorner> corners;
    std::vector<FacadeElement> elements;  // in outline order
    bool closed = false;
};

// Throws std::invalid_argument for fewer than two points in a feature, a point that is not finite, a
// zero-length edge, a gap between features, widths or ratio negative or not finite, a ZWE narrower
// than 1 cm, or more than 10000 walls asked of one base wall.
StoreyFacade subdivideStorey(const std::vector<std::vector<Vec2d>> &features, bool closed,
                             const WallSubdivision &subdivision);
// The same with a subdivision per feature (each module's style has its own): a corner face takes
// the width of the wall it lies on.
StoreyFacade subdivideStorey(const std::vector<std::vector<Vec2d>> &features, bool closed,
                             const std::vector<WallSubdivision> &subdivisions);

// The walls and ZWE of one base wall of free length `length` (Def 5.3), as widths in order:
// wall, ZWE, wall, …, wall. Throws std::invalid_argument as subdivideStorey does, and for a
// length that is negative or not finite.
std::vector<double> wallAndInterWallWidths(double length, const WallSubdivision &subdivision);

// Def 5.4: P_i = [h·a_i, h·a_{i+1}] for cuts 0 = a_1 < … < a_{n+1} = 1. Throws
// std::invalid_argument when the cuts do not rise strictly from 0 to 1 or the height is not
// positive and finite.
struct Partition {
    double zFrom = 0, zTo = 0;
};
std::vector<Partition> partitionHeights(double height, const std::vector<double> &cuts);

// A partition that consecutive elements along the outline share: elements first, first + 1, …,
// first + count − 1 (modulo the element count on a closed outline).
struct BandRun {
    size_t first = 0, count = 0;
    double zFrom = 0, zTo = 0;
    bool aroundTheOutline = false;  // every element of a closed outline: a ring with no ends
};

// The bands formed by equal partitions (to 1e-9 m) on neighbouring elements: each maximal run of
// elements sharing a partition, in outline order of its first element, then by height.
// `partitions` holds one list per element of `facade`.
std::vector<BandRun> findBands(const StoreyFacade &facade, const std::vector<std::vector<Partition>> &partitions);

}  // namespace veduta
