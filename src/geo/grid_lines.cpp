#include "geo/grid_lines.h"

#include <algorithm>

namespace veduta {

namespace {

GridLines::CellSpan cellsHolding(const std::vector<double> &lines, double lo, double hi) {
    int cells = int(lines.size()) - 1;
    if (lo == hi) {
        int k = int(std::lower_bound(lines.begin(), lines.end(), lo) - lines.begin());
        if (k < int(lines.size()) && lines[size_t(k)] == lo) {  // on line k: the cells k − 1 and k
            int first = std::max(k - 1, 0), last = std::min(k, cells - 1);
            return {first, std::max(last - first + 1, 0)};
        }
        return k >= 1 && k <= cells ? GridLines::CellSpan{k - 1, 1} : GridLines::CellSpan{};
    }
    int c = int(std::upper_bound(lines.begin(), lines.end(), lo) - lines.begin()) - 1;
    if (c < 0 || c >= cells || hi > lines[size_t(c) + 1]) return {};
    return {c, 1};
}

// The lines strictly between a and b, as a range of indices [first, last).
std::pair<size_t, size_t> linesBetween(const std::vector<double> &lines, double a, double b) {
    double lo = std::min(a, b), hi = std::max(a, b);
    auto first = std::upper_bound(lines.begin(), lines.end(), lo);
    auto last = std::lower_bound(first, lines.end(), hi);
    return {size_t(first - lines.begin()), size_t(last - lines.begin())};
}

double interpolateClamped(double t, double a, double b) {
    return std::clamp(a + t * (b - a), std::min(a, b), std::max(a, b));
}

// Appends the points after `a` up to and including `b`. Cutting at the middle line of the
// axis with more lines keeps the recursion shallow; each cut leaves fewer lines strictly
// inside each half (the cut point lies on its line), so it ends.
void splitSegment(Vec2d a, Vec2d b, const GridLines &lines, std::vector<Vec2d> &out) {
    auto [x0, x1] = linesBetween(lines.xs, a.x, b.x);
    auto [y0, y1] = linesBetween(lines.ys, a.y, b.y);
    if (x0 == x1 && y0 == y1) {
        out.push_back(b);
        return;
    }
    Vec2d cut;
    if (x1 - x0 >= y1 - y0) {
        double x = lines.xs[(x0 + x1) / 2];
        cut = {x, interpolateClamped((x - a.x) / (b.x - a.x), a.y, b.y)};
    } else {
        double y = lines.ys[(y0 + y1) / 2];
        cut = {interpolateClamped((y - a.y) / (b.y - a.y), a.x, b.x), y};
    }
    splitSegment(a, cut, lines, out);
    splitSegment(cut, b, lines, out);
}

}  // namespace

GridLines::CellSpan GridLines::columnsHolding(double lo, double hi) const { return cellsHolding(xs, lo, hi); }
GridLines::CellSpan GridLines::rowsHolding(double lo, double hi) const { return cellsHolding(ys, lo, hi); }

GridLines gridLines(const HeightGrid &grid, const LocalFrame &frame) {
    GridLines lines;
    lines.xs.reserve(size_t(grid.columns));
    lines.ys.reserve(size_t(grid.rows));
    for (int c = 0; c < grid.columns; ++c) lines.xs.push_back(toLocalDouble(grid.nodePoint(c, 0), frame).x);
    for (int r = 0; r < grid.rows; ++r) lines.ys.push_back(toLocalDouble(grid.nodePoint(0, r), frame).y);
    return lines;
}

Vec2d toLocalDouble(const MapPoint &p, const LocalFrame &frame) {
    return {p.easting - frame.origin.easting, p.northing - frame.origin.northing};
}

std::vector<Vec2d> splitAtGridLines(const std::vector<Vec2d> &line, const GridLines &lines, bool closed) {
    std::vector<Vec2d> out;
    if (line.empty()) return out;
    out.reserve(line.size() * 2);
    out.push_back(line.front());
    for (size_t i = 1; i < line.size(); ++i) splitSegment(line[i - 1], line[i], lines, out);
    if (closed && line.size() > 1) {
        splitSegment(line.back(), line.front(), lines, out);
        out.pop_back();  // the first point again
    }
    return out;
}

}  // namespace veduta
