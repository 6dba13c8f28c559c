// Where masonry may lie on one wall face (digest-001 §2.5, "Fitting bricks to a wall with holes",
// L1050–1054, after Legakis et al.): the face minus its openings grown by the mortar thickness, held
// twice. Once as the thesis's low-resolution grey image over the face's bounding rectangle, black
// where stones may lie and white where they may not, for the fast keep/drop test of a stone; and
// once exactly (CGAL, exact constructions) for the few stones that straddle a boundary.
//
// Choices where the thesis is open:
// * Only the openings are grown. The outline is not shrunk: the wall's edges meet corners, ZWE,
//   cornices and roofs, which are separate elements (L1013), so a stone cut at the edge reads as
//   running on behind them. The task's "wall face minus its openings grown by the mortar" says so.
// * "Grown by the mortar" is the Minkowski sum with an axis-parallel square of half-side `mortar`:
//   around the axis-parallel jambs, sills and lintels of openings this is the mitred parallel curve
//   of L1052, a joint exactly `mortar` wide; across a slanted or arched edge the joint is up to √2
//   times wider, never thinner.
// * The grey image is exact rather than sampled: a cell is black only when it lies wholly in the
//   free region, white only when wholly outside, grey where a boundary crosses it. A stone whose
//   mean grey is black is therefore kept whole and one whose mean is white dropped whole, without
//   error; only the grey ones are clipped (the thesis also drops "near white" stones, which would
//   lose masonry, so this does not).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/vecmath.h"
#include "facade/masonry.h"

namespace veduta {

// What the grey image says about a rectangle: its mean grey black, white or in between.
enum class MaskCover { Free, Blocked, Mixed };

// An x-range [low, high] of a horizontal strip.
struct Span {
    double low = 0, high = 0;
};

// The most cells the grey image holds; a finer request is coarsened to fit.
inline constexpr size_t kMaskCellLimit = size_t(1) << 22;

class WallMask {
  public:
    // The free region of `wall` with openings grown by `mortar` metres, imaged at `cellSize` metres
    // per cell (or coarser, to stay within kMaskCellLimit). The wall's outline and openings must be
    // simple, counter-clockwise and finite (an InternalError otherwise: they come from our code).
    WallMask(const WallFace &wall, double mortar, double cellSize);
    ~WallMask();
    WallMask(WallMask &&) noexcept;
    WallMask &operator=(WallMask &&) noexcept;

    // The bounding rectangle of the wall's outline, which the image covers.
    Vec2d low() const { return low_; }
    Vec2d high() const { return high_; }
    double cellSize() const { return cellSize_; }
    int columns() const { return columns_; }
    int rows() const { return rows_; }
    // The grey of a cell: 0 black (free), 1 white (forbidden), 0.5 where a boundary crosses it.
    // Row 0 is the bottom.
    float grey(int column, int row) const;

    // The mean grey under the rectangle [low, high] read as black, white or between, in constant
    // time. Outside the bounding rectangle counts as white.
    MaskCover cover(Vec2d low, Vec2d high) const;

    // The parts of `polygon` (counter-clockwise, simple) within the free region, exactly cut and
    // rounded to double: counter-clockwise, without holes (a part that would hold a hole, around an
    // opening smaller than it, is cut in two through the hole), possibly non-convex, and simple or,
    // as CGAL's Boolean results may be, touching itself at a vertex (two grown openings meeting at a
    // corner): facade/convex_pieces.h takes both.
    std::vector<std::vector<Vec2d>> clip(const std::vector<Vec2d> &polygon) const;

    // The x-ranges, within the bounding rectangle, where the whole strip low ≤ y ≤ high is free,
    // from the exact region; in increasing order.
    std::vector<Span> freeSpans(double low, double high) const;

    // The area of the free region, square metres.
    double freeArea() const;

  private:
    struct Exact;

    using Edge = std::pair<Vec2d, Vec2d>;

    void rasterise();
    std::optional<std::vector<std::vector<Vec2d>>> clipAlongAxes(const std::vector<Vec2d> &polygon) const;
    bool insideRings(Vec2d p) const;
    int rowOf(double y) const;
    uint32_t countIn(const std::vector<uint32_t> &table, int column0, int row0, int column1, int row1) const;

    std::unique_ptr<Exact> exact_;
    std::vector<Edge> edges_;  // the free region's rings rounded to double
    // Per row of the grey image, the edges whose y-range meets the row's (both closed): a clip
    // near an opening consults only those.
    std::vector<std::vector<uint32_t>> rowEdges_;
    Vec2d low_, high_;
    double cellSize_ = 0;
    int columns_ = 0, rows_ = 0;
    std::vector<uint8_t> cells_;  // 0 free, 1 crossed by a boundary, 2 forbidden; row-major from the bottom
    // Summed-area tables of free and of forbidden cells, (columns + 1) × (rows + 1).
    std::vector<uint32_t> freeSums_, blockedSums_;
};

}  // namespace veduta
