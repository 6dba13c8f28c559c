#include "facade/wall_mask.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "core/check.h"
#include "facade/convex_pieces.h"

namespace veduta {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

constexpr uint8_t kFreeCell = 0, kCrossedCell = 1, kBlockedCell = 2;

// A wall or opening outline as CGAL needs it: at least a triangle, finite, simple and
// counter-clockwise. Checked, since a violation would otherwise surface deep inside CGAL.
void checkOutline(const std::vector<Vec2d> &outline, const char *what) {
    VEDUTA_CHECK(outline.size() >= 3, fmt::format("a wall's {} has {} points", what, outline.size()));
    std::vector<CGAL::Epick::Point_2> points;
    for (Vec2d p : outline) {
        VEDUTA_CHECK(std::isfinite(p.x) && std::isfinite(p.y), fmt::format("a wall's {} is not finite", what));
        points.emplace_back(p.x, p.y);
    }
    VEDUTA_CHECK(CGAL::is_simple_2(points.begin(), points.end()), fmt::format("a wall's {} is not simple", what));
    VEDUTA_CHECK(CGAL::orientation_2(points.begin(), points.end()) == CGAL::COUNTERCLOCKWISE,
                 fmt::format("a wall's {} is not counter-clockwise", what));
}

Polygon toExact(const std::vector<Vec2d> &outline) { return cgalPolygon<Polygon>(outline); }

Polygon box(double lowX, double lowY, double highX, double highY) {
    return toExact({{lowX, lowY}, {highX, lowY}, {highX, highY}, {lowX, highY}});
}

bool isAxisParallelRectangle(const std::vector<Vec2d> &polygon) {
    return polygon.size() == 4 && polygon[0].y == polygon[1].y && polygon[1].x == polygon[2].x &&
        polygon[2].y == polygon[3].y && polygon[3].x == polygon[0].x && polygon[0].x < polygon[1].x &&
        polygon[1].y < polygon[2].y;
}

// The box a polygon encloses when every edge of it runs along the box's sides (corners and, as the
// refined edges of openings have them, points between); nullopt otherwise. A simple polygon whose
// edges all lie on its bounding box's sides is that box.
std::optional<std::pair<Vec2d, Vec2d>> boxOf(const std::vector<Vec2d> &polygon) {
    Vec2d low = polygon.front(), high = polygon.front();
    for (Vec2d p : polygon) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2d p = polygon[i], q = polygon[(i + 1) % polygon.size()];
        bool side = (p.x == q.x && (p.x == low.x || p.x == high.x)) || (p.y == q.y && (p.y == low.y || p.y == high.y));
        if (!side) return std::nullopt;
    }
    return std::make_pair(low, high);
}

// The opening grown by an axis-parallel square of half-side `mortar` (see the header). Most
// openings are axis-parallel rectangles, whose sum with the square is the rectangle widened by
// the mortar on every side: the same region without the convolution.
PolygonWithHoles grown(const std::vector<Vec2d> &opening, double mortar) {
    if (mortar == 0) return PolygonWithHoles(toExact(opening));
    if (auto box = boxOf(opening)) {
        // In exact numbers, as the sum's corners are.
        const Kernel::FT m(mortar), x0 = Kernel::FT(box->first.x) - m, y0 = Kernel::FT(box->first.y) - m,
                                    x1 = Kernel::FT(box->second.x) + m, y1 = Kernel::FT(box->second.y) + m;
        std::vector<Kernel::Point_2> corners{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
        return PolygonWithHoles(Polygon(corners.begin(), corners.end()));
    }
    return CGAL::minkowski_sum_2(toExact(opening), box(-mortar, -mortar, mortar, mortar));
}

bool overlaps(const CGAL::Bbox_2 &a, const CGAL::Bbox_2 &b) {
    return a.xmin() < b.xmax() && b.xmin() < a.xmax() && a.ymin() < b.ymax() && b.ymin() < a.ymax();
}

// `part` as polygons without holes: while it has one, cut it by the vertical line through the
// middle of that hole, which opens the hole into both halves' outer boundaries.
void appendWithoutHoles(const PolygonWithHoles &part, std::vector<std::vector<Vec2d>> &out) {
    if (part.number_of_holes() == 0) {
        std::vector<Vec2d> points = roundedRing(part.outer_boundary());
        if (points.size() >= 3) out.push_back(std::move(points));
        return;
    }
    CGAL::Bbox_2 whole = part.outer_boundary().bbox();
    CGAL::Bbox_2 hole = part.holes_begin()->bbox();
    double cut = 0.5 * (hole.xmin() + hole.xmax());
    for (const Polygon &half : {box(whole.xmin() - 1, whole.ymin() - 1, cut, whole.ymax() + 1),
                                box(cut, whole.ymin() - 1, whole.xmax() + 1, whole.ymax() + 1)}) {
        std::vector<PolygonWithHoles> pieces;
        CGAL::intersection(part, half, std::back_inserter(pieces));
        for (const PolygonWithHoles &piece : pieces) appendWithoutHoles(piece, out);
    }
}

}  // namespace

// The free region, split into its connected parts with their boxes, so that a clip consults only
// the boundaries near the clipped polygon.
struct WallMask::Exact {
    struct Part {
        Polygon outer;
        CGAL::Bbox_2 outerBox;
        std::vector<Polygon> holes;
        std::vector<CGAL::Bbox_2> holeBoxes;
    };
    PolygonSet region;
    std::vector<Part> parts;
};

WallMask::WallMask(const WallFace &wall, double mortar, double cellSize) : exact_(std::make_unique<Exact>()) {
    VEDUTA_CHECK(std::isfinite(mortar) && mortar >= 0, fmt::format("mortar thickness {}", mortar));
    VEDUTA_CHECK(std::isfinite(cellSize) && cellSize > 0, fmt::format("mask cell size {}", cellSize));
    checkOutline(wall.outline, "outline");
    for (const auto &opening : wall.openings) checkOutline(opening, "opening");

    low_ = high_ = wall.outline.front();
    for (Vec2d p : wall.outline) {
        low_ = {std::min(low_.x, p.x), std::min(low_.y, p.y)};
        high_ = {std::max(high_.x, p.x), std::max(high_.y, p.y)};
    }
    Vec2d size = high_ - low_;
    cellSize_ = cellSize;
    while (std::ceil(size.x / cellSize_) * std::ceil(size.y / cellSize_) > double(kMaskCellLimit)) cellSize_ *= 1.25;
    columns_ = std::max(1, int(std::ceil(size.x / cellSize_)));
    rows_ = std::max(1, int(std::ceil(size.y / cellSize_)));

    exact_->region = PolygonSet(toExact(wall.outline));
    // One aggregated union of the openings, then one difference: a difference per opening would
    // sweep the growing region once for each.
    if (!wall.openings.empty()) {
        std::vector<PolygonWithHoles> openings;
        for (const auto &opening : wall.openings) openings.push_back(grown(opening, mortar));
        PolygonSet cut;
        cut.join(openings.begin(), openings.end());
        exact_->region.difference(cut);
    }
    std::vector<PolygonWithHoles> parts;
    exact_->region.polygons_with_holes(std::back_inserter(parts));
    for (const PolygonWithHoles &part : parts) {
        Exact::Part entry{part.outer_boundary(), part.outer_boundary().bbox(), {}, {}};
        for (const Polygon &hole : part.holes()) {
            entry.holes.push_back(hole);
            entry.holeBoxes.push_back(hole.bbox());
        }
        exact_->parts.push_back(std::move(entry));
    }
    rasterise();
}

WallMask::~WallMask() = default;
WallMask::WallMask(WallMask &&) noexcept = default;
WallMask &WallMask::operator=(WallMask &&) noexcept = default;

// Marks every cell whose inside a boundary edge enters, then decides the others by the parity of
// the boundary crossings left of their centres, one scanline per row. An edge along a cell's side
// (the wall's own edges lie on the image's border) enters neither cell beside it, so the cells
// along the wall's edges stay black and the bricks there are kept whole without a cut. The rings
// are the exact region rounded to double: a cell may misjudge a boundary within a rounding error of
// its side, which moves a stone's edge by no more than rounding its corners does.
void WallMask::rasterise() {
    std::vector<Edge> &edges = edges_;
    for (const Exact::Part &part : exact_->parts) {
        auto addRing = [&](const Polygon &ring) {
            std::vector<Vec2d> points = roundedRing(ring);
            for (size_t i = 0; i < points.size(); ++i) edges.emplace_back(points[i], points[(i + 1) % points.size()]);
        };
        addRing(part.outer);
        for (const Polygon &hole : part.holes) addRing(hole);
    }
    rowEdges_.assign(size_t(rows_), {});
    for (size_t e = 0; e < edges.size(); ++e) {
        auto [p, q] = edges[e];
        for (int row = rowOf(std::min(p.y, q.y)); row <= rowOf(std::max(p.y, q.y)); ++row)
            rowEdges_[size_t(row)].push_back(uint32_t(e));
    }
    cells_.assign(size_t(columns_) * size_t(rows_), kBlockedCell);
    std::vector<bool> crossed(cells_.size(), false);
    // The first and last cell whose open inside meets [low, high] (none when both lie on one side).
    auto firstCell = [&](double offset, int count) {
        return int(std::clamp(std::floor(offset / cellSize_), 0.0, double(count)));
    };
    auto lastCell = [&](double offset, int count) {
        return int(std::clamp(std::ceil(offset / cellSize_) - 1, -1.0, double(count - 1)));
    };
    for (const Edge &edge : edges) {
        Vec2d p = edge.first, q = edge.second;  // not a structured binding: clang cannot capture one
        double lowY = std::min(p.y, q.y), highY = std::max(p.y, q.y);
        int row0 = firstCell(lowY - low_.y, rows_), row1 = lastCell(highY - low_.y, rows_);
        for (int row = row0; row <= row1; ++row) {
            double ya = std::clamp(low_.y + row * cellSize_, lowY, highY);
            double yb = std::clamp(low_.y + (row + 1) * cellSize_, lowY, highY);
            auto xAt = [&](double y) { return p.y == q.y ? p.x : p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y); };
            double xa = p.y == q.y ? std::min(p.x, q.x) : std::min(xAt(ya), xAt(yb));
            double xb = p.y == q.y ? std::max(p.x, q.x) : std::max(xAt(ya), xAt(yb));
            int column0 = firstCell(xa - low_.x, columns_), column1 = lastCell(xb - low_.x, columns_);
            for (int column = column0; column <= column1; ++column) crossed[size_t(row) * columns_ + column] = true;
        }
    }
    std::vector<double> crossings;
    for (int row = 0; row < rows_; ++row) {
        double y = low_.y + (row + 0.5) * cellSize_;
        crossings.clear();
        for (auto [p, q] : edges) {
            if ((p.y <= y) != (q.y <= y)) crossings.push_back(p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y));
        }
        std::sort(crossings.begin(), crossings.end());
        size_t left = 0;
        for (int column = 0; column < columns_; ++column) {
            double x = low_.x + (column + 0.5) * cellSize_;
            while (left < crossings.size() && crossings[left] < x) ++left;
            size_t index = size_t(row) * columns_ + column;
            if (crossed[index]) cells_[index] = kCrossedCell;
            else if (left % 2 == 1) cells_[index] = kFreeCell;
        }
    }
    size_t stride = size_t(columns_) + 1;
    freeSums_.assign(stride * (rows_ + 1), 0);
    blockedSums_.assign(stride * (rows_ + 1), 0);
    for (int row = 0; row < rows_; ++row) {
        for (int column = 0; column < columns_; ++column) {
            uint8_t cell = cells_[size_t(row) * columns_ + column];
            size_t at = (row + 1) * stride + column + 1;
            freeSums_[at] =
                (cell == kFreeCell) + freeSums_[at - 1] + freeSums_[at - stride] - freeSums_[at - stride - 1];
            blockedSums_[at] = (cell == kBlockedCell) + blockedSums_[at - 1] + blockedSums_[at - stride] -
                blockedSums_[at - stride - 1];
        }
    }
}

float WallMask::grey(int column, int row) const {
    VEDUTA_CHECK(column >= 0 && column < columns_ && row >= 0 && row < rows_, "a mask cell outside the image");
    return float(cells_[size_t(row) * columns_ + column]) * 0.5f;
}

uint32_t WallMask::countIn(const std::vector<uint32_t> &table, int column0, int row0, int column1, int row1) const {
    size_t stride = size_t(columns_) + 1;
    return table[(row1 + 1) * stride + column1 + 1] - table[row0 * stride + column1 + 1] -
        table[(row1 + 1) * stride + column0] + table[row0 * stride + column0];
}

MaskCover WallMask::cover(Vec2d low, Vec2d high) const {
    // The cells the rectangle touches, widened by a rounding margin: a wider set only makes
    // "free" and "blocked" harder to reach, never wrong.
    constexpr double kMargin = 1e-9;
    auto first = [&](double offset, int count) {
        return int(std::clamp(std::floor(offset / cellSize_ - kMargin), -1.0, double(count)));
    };
    auto last = [&](double offset, int count) {
        return int(std::clamp(std::ceil(offset / cellSize_ + kMargin) - 1, -1.0, double(count)));
    };
    int column0 = first(low.x - low_.x, columns_), column1 = last(high.x - low_.x, columns_);
    int row0 = first(low.y - low_.y, rows_), row1 = last(high.y - low_.y, rows_);
    bool outside = low.x < low_.x || low.y < low_.y || high.x > high_.x || high.y > high_.y;
    column0 = std::max(column0, 0), row0 = std::max(row0, 0);
    column1 = std::min(column1, columns_ - 1), row1 = std::min(row1, rows_ - 1);
    if (column0 > column1 || row0 > row1) return MaskCover::Blocked;
    uint32_t total = uint32_t(column1 - column0 + 1) * uint32_t(row1 - row0 + 1);
    if (!outside && countIn(freeSums_, column0, row0, column1, row1) == total) return MaskCover::Free;
    if (countIn(blockedSums_, column0, row0, column1, row1) == total) return MaskCover::Blocked;
    return MaskCover::Mixed;
}

namespace {

// The boundary of the kept cells of a grid (xs × ys, cell (i, j) kept when keep[j · columns + i]),
// as counter-clockwise rings without collinear corners; nullopt when it is not a set of simple
// rings without holes: a hole (a clockwise ring) or cells that touch only at a corner.
std::optional<std::vector<std::vector<Vec2d>>> traceCells(const std::vector<double> &xs, const std::vector<double> &ys,
                                                          const std::vector<bool> &keep) {
    int columns = int(xs.size()) - 1, rows = int(ys.size()) - 1;
    auto kept = [&](int i, int j) {
        return i >= 0 && i < columns && j >= 0 && j < rows && keep[size_t(j * columns + i)];
    };
    // Grid corners by index; each boundary edge runs with the kept cell on its left.
    std::map<std::pair<int, int>, std::pair<int, int>> next;
    auto addEdge = [&](std::pair<int, int> from, std::pair<int, int> to) { return next.emplace(from, to).second; };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            if (!kept(i, j)) continue;
            bool simple = (kept(i, j - 1) || addEdge({i, j}, {i + 1, j})) &&
                (kept(i + 1, j) || addEdge({i + 1, j}, {i + 1, j + 1})) &&
                (kept(i, j + 1) || addEdge({i + 1, j + 1}, {i, j + 1})) &&
                (kept(i - 1, j) || addEdge({i, j + 1}, {i, j}));
            if (!simple) return std::nullopt;  // two edges leave one corner: cells touching at a corner
        }
    std::vector<std::vector<Vec2d>> rings;
    while (!next.empty()) {
        std::vector<std::pair<int, int>> corners;
        auto at = next.begin()->first;
        while (next.count(at)) {
            corners.push_back(at);
            auto to = next[at];
            next.erase(at);
            at = to;
        }
        std::vector<Vec2d> ring;
        double twiceArea = 0;
        for (size_t k = 0; k < corners.size(); ++k) {
            auto before = corners[(k + corners.size() - 1) % corners.size()], after = corners[(k + 1) % corners.size()];
            auto c = corners[k];
            bool straight = (before.first == c.first && c.first == after.first) ||
                (before.second == c.second && c.second == after.second);
            if (!straight) ring.push_back({xs[size_t(c.first)], ys[size_t(c.second)]});
        }
        for (size_t k = 0; k < ring.size(); ++k) twiceArea += cross(ring[k], ring[(k + 1) % ring.size()]);
        if (twiceArea <= 0) return std::nullopt;
        rings.push_back(std::move(ring));
    }
    return rings;
}

}  // namespace

// A stone is mostly an axis-parallel rectangle and the boundaries it straddles mostly the jambs,
// sills and lintels of rectangular openings grown by the mortar. Such a cut needs no exact
// Boolean: the boundary's coordinates inside the rectangle cut it into a few cells, each wholly
// free or wholly not (decided at its centre by the rounded rings), and the free cells' outline
// is the piece. Anything else (a slanted edge, a hole, cells meeting at a corner) is left to the
// exact path. The rings are the exact region rounded to double, as the grey image's are.
std::optional<std::vector<std::vector<Vec2d>>> WallMask::clipAlongAxes(const std::vector<Vec2d> &polygon) const {
    if (!isAxisParallelRectangle(polygon)) return std::nullopt;
    Vec2d low = polygon[0], high = polygon[2];
    std::vector<double> xs{low.x, high.x}, ys{low.y, high.y};
    // An edge spanning several rows comes once for each: its cuts are merged below.
    for (int row = rowOf(low.y); row <= rowOf(high.y); ++row)
        for (uint32_t e : rowEdges_[size_t(row)]) {
            auto [p, q] = edges_[e];
            if (std::max(p.x, q.x) < low.x || std::min(p.x, q.x) > high.x || std::max(p.y, q.y) < low.y ||
                std::min(p.y, q.y) > high.y)
                continue;
            if (p.x != q.x && p.y != q.y) return std::nullopt;
            for (double x : {p.x, q.x})
                if (x > low.x && x < high.x) xs.push_back(x);
            for (double y : {p.y, q.y})
                if (y > low.y && y < high.y) ys.push_back(y);
        }
    for (auto *cuts : {&xs, &ys}) {
        std::sort(cuts->begin(), cuts->end());
        cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
    }
    int columns = int(xs.size()) - 1, rows = int(ys.size()) - 1;
    std::vector<bool> keep(size_t(columns) * size_t(rows));
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i)
            keep[size_t(j * columns + i)] =
                insideRings({0.5 * (xs[size_t(i)] + xs[size_t(i) + 1]), 0.5 * (ys[size_t(j)] + ys[size_t(j) + 1])});
    return traceCells(xs, ys, keep);
}

// The grey image's row holding height y, clamped to the image: monotonic in y, so an edge and a
// query whose y-ranges meet share a row.
int WallMask::rowOf(double y) const {
    return int(std::clamp(std::floor((y - low_.y) / cellSize_), 0.0, double(rows_ - 1)));
}

// Even-odd over the rounded rings: the free region, holes and all. Every edge a horizontal line
// at p.y crosses has p.y in its y-range, so it is listed at p.y's row.
bool WallMask::insideRings(Vec2d p) const {
    bool inside = false;
    for (uint32_t e : rowEdges_[size_t(rowOf(p.y))]) {
        auto [a, b] = edges_[e];
        if ((a.y <= p.y) != (b.y <= p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

std::vector<std::vector<Vec2d>> WallMask::clip(const std::vector<Vec2d> &polygon) const {
    // The common cut at the wall's rim: an axis-parallel rectangle reaching past the bounding
    // rectangle whose part within it is wholly free is that part, without an exact sweep.
    if (polygon.size() == 4 && polygon[0].y == polygon[1].y && polygon[1].x == polygon[2].x &&
        polygon[2].y == polygon[3].y && polygon[3].x == polygon[0].x) {
        Vec2d low{std::max(std::min(polygon[0].x, polygon[2].x), low_.x),
                  std::max(std::min(polygon[0].y, polygon[2].y), low_.y)};
        Vec2d high{std::min(std::max(polygon[0].x, polygon[2].x), high_.x),
                   std::min(std::max(polygon[0].y, polygon[2].y), high_.y)};
        if (!(low.x < high.x && low.y < high.y)) return {};
        if (cover(low, high) == MaskCover::Free) return {{low, {high.x, low.y}, high, {low.x, high.y}}};
    }
    if (auto pieces = clipAlongAxes(polygon)) return std::move(*pieces);
    Polygon subject = toExact(polygon);
    CGAL::Bbox_2 bounds = subject.bbox();
    std::vector<std::vector<Vec2d>> out;
    for (const Exact::Part &part : exact_->parts) {
        if (!overlaps(bounds, part.outerBox)) continue;
        // Holes whose boxes miss the subject cannot cut it: leave them out of the sweep.
        PolygonWithHoles local(part.outer);
        for (size_t i = 0; i < part.holes.size(); ++i) {
            if (overlaps(bounds, part.holeBoxes[i])) local.add_hole(part.holes[i]);
        }
        std::vector<PolygonWithHoles> pieces;
        CGAL::intersection(subject, local, std::back_inserter(pieces));
        for (const PolygonWithHoles &piece : pieces) appendWithoutHoles(piece, out);
    }
    return out;
}

std::vector<Span> WallMask::freeSpans(double low, double high) const {
    PolygonSet blocked(box(low_.x, low, high_.x, high));
    blocked.difference(exact_->region);
    std::vector<PolygonWithHoles> parts;
    blocked.polygons_with_holes(std::back_inserter(parts));
    std::vector<Span> taken;
    for (const PolygonWithHoles &part : parts) {
        // Epeck's boxes enclose the exact coordinates, so a span never reaches into a blocked part.
        CGAL::Bbox_2 bounds = part.outer_boundary().bbox();
        taken.push_back({bounds.xmin(), bounds.xmax()});
    }
    std::sort(taken.begin(), taken.end(), [](Span a, Span b) { return a.low < b.low; });
    std::vector<Span> spans;
    double x = low_.x;
    for (Span span : taken) {
        if (span.low > x) spans.push_back({x, span.low});
        x = std::max(x, span.high);
    }
    if (x < high_.x) spans.push_back({x, high_.x});
    return spans;
}

double WallMask::freeArea() const {
    double area = 0;
    for (const Exact::Part &part : exact_->parts) {
        area += CGAL::to_double(part.outer.area());
        for (const Polygon &hole : part.holes) area -= std::abs(CGAL::to_double(hole.area()));
    }
    return area;
}

}  // namespace veduta
