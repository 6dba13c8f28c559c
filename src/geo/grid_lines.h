// The lines of a DGM's grid in the local frame, in double, and the splitting of polylines
// where they cross them (Rilling 2006, §4.5 step 1): draping and ribbons cut their outlines and
// centre lines there so that every piece lies in one grid cell.
#pragma once

#include <vector>

#include "geo/height_grid.h"
#include "geodesy/local_frame.h"

namespace veduta {

struct GridLines {
    std::vector<double> xs;  // column lines from the west, strictly increasing
    std::vector<double> ys;  // row lines from the south, strictly increasing

    // The cells along one axis (cell c lies between line c and c + 1) whose closed band holds
    // [lo, hi]: one, or two when lo == hi lies on an inner line, or none outside the grid or
    // when the range spans a line.
    struct CellSpan {
        int first = 0, count = 0;
    };
    CellSpan columnsHolding(double lo, double hi) const;
    CellSpan rowsHolding(double lo, double hi) const;
};

// The grid's node lines in the local frame: west + c·spacing − origin, computed as
// HeightGrid::nodePoint does and then made local, so every caller gets the same doubles.
GridLines gridLines(const HeightGrid &grid, const LocalFrame &frame);

Vec2d toLocalDouble(const MapPoint &p, const LocalFrame &frame);

// `line` with a point inserted wherever a segment crosses a grid line strictly between its ends
// (Rilling 2006 (digest §8) test 13). An inserted point lies exactly on its line (that coordinate is the
// line's double); the other coordinate is interpolated and clamped to the segment's range, so
// that every resulting segment lies in one closed cell even where rounding would misorder two
// crossings near a node. The lines run on beyond the grid (outlines leaving the grid are cut
// where they pass its rows, which is what the inside tests by rows need). With `closed`, the segment from the last
// point back to the first is cut too and the result stays a ring (its first point not repeated).
std::vector<Vec2d> splitAtGridLines(const std::vector<Vec2d> &line, const GridLines &lines, bool closed);

}  // namespace veduta
