#include "geo/drape_areas.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <unordered_map>

#include <fmt/format.h>

#include "core/error.h"
#include "geo/grid_lines.h"
#include "geo/mesh_normals.h"

namespace veduta {

namespace {

// Two triangulations of a touched cell. Usually no two constraints cross inside a cell but
// the outlines and the diagonal, whose crossings are cut in beforehand (cutAtDiagonal), so a
// triangulation over doubles with exact predicates needs no constructions at all and is
// exact. Where outlines cross each other inside a cell (overlapping areas) it throws, and the
// cell is triangulated again with exact constructions (CGAL's Epeck), the diagonal left
// whole and every crossing computed exactly.
struct NodeInfo {
    int64_t node = -1;  // the grid node a cell corner is, or −1
};
template <typename K, typename Tag>
using CellCdt = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<NodeInfo, K>,
                                         CGAL::Constrained_triangulation_face_base_2<K>>,
    Tag>;
using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using FastCdt = CellCdt<Inexact, CGAL::No_constraint_intersection_requiring_constructions_tag>;
// The _plus_ variant keeps the input constraints, so crossing outlines are intersected once
// from their input segments, not again from pieces already cut (CGAL's advice for exact
// number types).
using ExactCdt = CGAL::Constrained_triangulation_plus_2<CellCdt<Exact, CGAL::Exact_intersections_tag>>;

struct OutlineEdge {
    Vec2d a, b;
    uint32_t area = 0;
};

// A piece of outline (or, with a == b, one of its points) filed under a grid cell.
struct CellItem {
    size_t cell = 0;
    Vec2d a, b;
};

struct PieceVertex {
    int64_t node = -1;  // a grid node, or −1: then `at` names the vertex
    Vec2d at;
    float height = 0;
};

struct Piece {
    std::array<PieceVertex, 3> corners;
    uint32_t area = kNoArea;
};

// The grid with its lines, and which of its cells have data.
struct DrapeGrid {
    const HeightGrid &heights;
    GridLines lines;
    int cellColumns = 0, cellRows = 0;

    size_t cellIndex(int c, int r) const { return size_t(r) * size_t(cellColumns) + size_t(c); }
    int64_t nodeIndex(int c, int r) const { return int64_t(r) * heights.columns + c; }
    bool cellHasData(int c, int r) const {
        return !std::isnan(heights.node(c, r)) && !std::isnan(heights.node(c + 1, r)) &&
            !std::isnan(heights.node(c, r + 1)) && !std::isnan(heights.node(c + 1, r + 1));
    }
    // The grid's surface at p in cell (c, r): the SW–NE diagonal splits the cell into a
    // south-east and a north-west triangle. The weights make nodes and cell edges exact (a
    // point on an edge reads only that edge's two nodes), so both cells give a shared
    // vertex the same height.
    float heightIn(int c, int r, Vec2d p) const {
        double u = (p.x - lines.xs[size_t(c)]) / (lines.xs[size_t(c) + 1] - lines.xs[size_t(c)]);
        double v = (p.y - lines.ys[size_t(r)]) / (lines.ys[size_t(r) + 1] - lines.ys[size_t(r)]);
        double h00 = heights.node(c, r), h11 = heights.node(c + 1, r + 1);
        if (u >= v) return float((1 - u) * h00 + (u - v) * double(heights.node(c + 1, r)) + v * h11);
        return float((1 - v) * h00 + (v - u) * double(heights.node(c, r + 1)) + u * h11);
    }
};

std::string areaName(const std::vector<DrapeArea> &areas, size_t i) {
    return areas[i].name.empty() ? fmt::format("drape area {} (object {})", i, areas[i].objectIndex) : areas[i].name;
}

// The outlines in the local frame, cut at the grid lines, without repeated points.
std::vector<std::vector<Vec2d>> cutOutlines(const std::vector<DrapeArea> &areas, const LocalFrame &frame,
                                            const GridLines &lines) {
    std::vector<std::vector<Vec2d>> rings;
    rings.reserve(areas.size());
    for (size_t i = 0; i < areas.size(); ++i) {
        std::vector<Vec2d> ring;
        for (const MapPoint &p : areas[i].outline) {
            if (!std::isfinite(p.easting) || !std::isfinite(p.northing)) {
                throw InputError(FileLoc{}, fmt::format("{}: a point is not a finite number", areaName(areas, i)));
            }
            Vec2d local = toLocalDouble(p, frame);
            if (ring.empty() || !(ring.back() == local)) ring.push_back(local);
        }
        while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
        std::vector<Vec2d> sorted = ring;
        std::sort(sorted.begin(), sorted.end(),
                  [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
        if (std::unique(sorted.begin(), sorted.end()) - sorted.begin() < 3) {
            throw InputError(FileLoc{},
                             fmt::format("{}: an outline needs at least 3 distinct points", areaName(areas, i)));
        }
        rings.push_back(splitAtGridLines(ring, lines, true));
    }
    return rings;
}

template <typename F>
void forEachEdge(const std::vector<Vec2d> &ring, F &&f) {
    for (size_t i = 0; i < ring.size(); ++i) f(ring[i], ring[(i + 1) % ring.size()]);
}

// The outline edges by grid row, for the inside tests: every edge that is not horizontal lies
// within one row's band once the outlines are cut. Rows hold edges beyond the grid's columns
// too, since a ray along the row crosses them, and are sorted by each edge's east end.
std::vector<std::vector<OutlineEdge>> edgesByRow(const std::vector<std::vector<Vec2d>> &rings, const DrapeGrid &g) {
    std::vector<std::vector<OutlineEdge>> rows(size_t(g.cellRows));
    for (size_t i = 0; i < rings.size(); ++i) {
        forEachEdge(rings[i], [&](Vec2d a, Vec2d b) {
            if (a.y == b.y) return;
            GridLines::CellSpan span = g.lines.rowsHolding(std::min(a.y, b.y), std::max(a.y, b.y));
            if (span.count == 1) rows[size_t(span.first)].push_back({a, b, uint32_t(i)});
        });
    }
    for (std::vector<OutlineEdge> &row : rows) {  // by their east end, for areaAt
        std::stable_sort(row.begin(), row.end(), [](const OutlineEdge &e, const OutlineEdge &f) {
            return std::max(e.a.x, e.b.x) < std::max(f.a.x, f.b.x);
        });
    }
    return rows;
}

// Every outline edge and point under each cell whose closed square holds it (an edge along
// a grid line goes to the cells on both sides, a point on a node to all four), sorted by cell.
// Filing the points too makes a cell that an outline only touches insert the touching point,
// so both cells at a shared edge split it alike.
std::vector<CellItem> itemsByCell(const std::vector<std::vector<Vec2d>> &rings, const DrapeGrid &g) {
    std::vector<CellItem> items;
    auto file = [&](Vec2d a, Vec2d b) {
        GridLines::CellSpan columns = g.lines.columnsHolding(std::min(a.x, b.x), std::max(a.x, b.x));
        GridLines::CellSpan rows = g.lines.rowsHolding(std::min(a.y, b.y), std::max(a.y, b.y));
        for (int r = rows.first; r < rows.first + rows.count; ++r) {
            for (int c = columns.first; c < columns.first + columns.count; ++c)
                items.push_back({g.cellIndex(c, r), a, b});
        }
    };
    for (const std::vector<Vec2d> &ring : rings) {
        forEachEdge(ring, file);
        for (Vec2d p : ring) file(p, p);
    }
    std::stable_sort(items.begin(), items.end(), [](const CellItem &x, const CellItem &y) { return x.cell < y.cell; });
    return items;
}

// Picks the winner among the areas that an inside test crossed an odd number of times.
class AreaRanking {
  public:
    explicit AreaRanking(const std::vector<DrapeArea> &areas) {
        priorities_.reserve(areas.size());
        for (const DrapeArea &area : areas) priorities_.push_back(drapePriority(area.landClass));
    }
    bool better(uint32_t a, uint32_t b) const {
        return b == kNoArea || priorities_[a] > priorities_[b] || (priorities_[a] == priorities_[b] && a < b);
    }
    // `crossed` lists an area once per crossing (and is sorted here): the areas crossed an odd
    // number of times hold the point. Sorting the few crossings costs nothing per area, so
    // thousands of areas do not slow each piece down.
    uint32_t winner(std::vector<uint32_t> &crossed) const {
        std::sort(crossed.begin(), crossed.end());
        uint32_t best = kNoArea;
        for (size_t i = 0; i < crossed.size();) {
            size_t end = i;
            while (end < crossed.size() && crossed[end] == crossed[i]) ++end;
            if ((end - i) % 2 == 1 && better(crossed[i], best)) best = crossed[i];
            i = end;
        }
        return best;
    }
    size_t size() const { return priorities_.size(); }

  private:
    std::vector<int> priorities_;
};

// The area of the piece around p, a point strictly inside a cell of the row: a ray from p to
// +x and the even–odd rule, each edge counting half-open in y. Cheap bounds decide most
// edges; the rest take CGAL's exact predicates, so a thin piece along an outline is judged
// right.
template <typename K>
uint32_t areaAt(const typename K::Point_2 &p, const std::vector<OutlineEdge> &row, const AreaRanking &ranking,
                std::vector<uint32_t> &crossed) {
    using Point = typename K::Point_2;
    constexpr double kMargin = 1e-6;  // metres; far above the centroid's rounding
    double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
    crossed.clear();
    // Edges ending west of p cannot cross the ray.
    auto first = std::lower_bound(row.begin(), row.end(), px - kMargin,
                                  [](const OutlineEdge &e, double x) { return std::max(e.a.x, e.b.x) < x; });
    for (auto it = first; it != row.end(); ++it) {
        const OutlineEdge &e = *it;
        double yLo = std::min(e.a.y, e.b.y), yHi = std::max(e.a.y, e.b.y);
        if (yHi < py - kMargin || yLo > py + kMargin || std::max(e.a.x, e.b.x) < px - kMargin) continue;
        if (std::min(e.a.x, e.b.x) > px + kMargin && yLo < py - kMargin && yHi > py + kMargin) {
            crossed.push_back(e.area);
            continue;
        }
        Point a(e.a.x, e.a.y), b(e.b.x, e.b.y);
        bool aBelow = CGAL::compare_y(a, p) != CGAL::LARGER;
        bool bBelow = CGAL::compare_y(b, p) != CGAL::LARGER;
        if (aBelow == bBelow) continue;
        CGAL::Orientation side = CGAL::orientation(a, b, p);
        if (side == (aBelow ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN)) crossed.push_back(e.area);
    }
    return ranking.winner(crossed);
}

using Segment = std::pair<Vec2d, Vec2d>;

// The cell's outline items with every crossing of the SW–NE diagonal cut in (the point
// rounded to double, so within a rounding of the diagonal), and the diagonal in pieces
// through those points and through outline points lying on it.
struct CutCell {
    std::vector<Vec2d> points;
    std::vector<Segment> segments;
    std::vector<Vec2d> diagonal;  // from the SW corner to the NE corner
};

// nullopt where a cut point rounds onto the cell's side (a crossing within a rounding of a
// corner): the neighbour would not have it, so the exact triangulation takes the cell.
std::optional<CutCell> cutAtDiagonal(Vec2d sw, Vec2d ne, const CellItem *items, size_t count) {
    using P = Inexact::Point_2;
    P p0(sw.x, sw.y), p1(ne.x, ne.y);
    auto side = [&](Vec2d p) { return CGAL::orientation(p0, p1, P(p.x, p.y)); };
    auto determinant = [&](Vec2d p) { return (ne.x - sw.x) * (p.y - sw.y) - (ne.y - sw.y) * (p.x - sw.x); };
    CutCell cell;
    std::vector<Vec2d> onDiagonal;
    for (size_t i = 0; i < count; ++i) {
        Vec2d a = items[i].a, b = items[i].b;
        if (side(a) == CGAL::COLLINEAR) onDiagonal.push_back(a);
        if (a == b) {
            cell.points.push_back(a);
            continue;
        }
        if (side(b) == CGAL::COLLINEAR) onDiagonal.push_back(b);
        CGAL::Orientation sa = side(a), sb = side(b);
        if (sa == CGAL::COLLINEAR || sb == CGAL::COLLINEAR || sa == sb) {
            cell.segments.push_back({a, b});
            continue;
        }
        double da = determinant(a), db = determinant(b), t = da / (da - db);
        Vec2d cut{std::clamp(a.x + t * (b.x - a.x), std::min(a.x, b.x), std::max(a.x, b.x)),
                  std::clamp(a.y + t * (b.y - a.y), std::min(a.y, b.y), std::max(a.y, b.y))};
        bool onSide = cut.x == sw.x || cut.x == ne.x || cut.y == sw.y || cut.y == ne.y;
        if (onSide && !(cut == sw) && !(cut == ne)) return std::nullopt;
        onDiagonal.push_back(cut);
        if (!(cut == a)) cell.segments.push_back({a, cut});
        if (!(cut == b)) cell.segments.push_back({cut, b});
    }
    std::sort(onDiagonal.begin(), onDiagonal.end(),
              [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    onDiagonal.erase(std::unique(onDiagonal.begin(), onDiagonal.end()), onDiagonal.end());
    cell.diagonal.push_back(sw);
    for (Vec2d p : onDiagonal) {
        if (!(p == sw) && !(p == ne)) cell.diagonal.push_back(p);
    }
    cell.diagonal.push_back(ne);
    return cell;
}

// The faces of a finished triangulation as pieces, each given the area around its centroid
// and its corners their heights.
template <typename Cdt>
void collectPieces(const Cdt &cdt, const DrapeGrid &g, int c, int r, const std::vector<OutlineEdge> &row,
                   const AreaRanking &ranking, std::vector<Piece> &pieces) {
    using K = typename Cdt::Geom_traits;
    std::vector<uint32_t> crossed;
    for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) {
        Piece piece;
        for (int k = 0; k < 3; ++k) {
            auto v = face->vertex(k);
            PieceVertex &out = piece.corners[size_t(k)];
            out.node = v->info().node;
            out.at = {CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())};
            out.height = out.node >= 0 ? g.heights.heights[size_t(out.node)] : g.heightIn(c, r, out.at);
        }
        typename K::Point_2 centroid =
            CGAL::centroid(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point());
        piece.area = areaAt<K>(centroid, row, ranking, crossed);
        pieces.push_back(piece);
    }
}

template <typename Cdt>
void insertCorners(Cdt &cdt, const DrapeGrid &g, int c, int r) {
    for (int k = 0; k < 4; ++k) {
        int nc = c + (k & 1), nr = r + (k >> 1);
        auto v = cdt.insert(typename Cdt::Point(g.lines.xs[size_t(nc)], g.lines.ys[size_t(nr)]));
        v->info().node = g.nodeIndex(nc, nr);
    }
}

// The pieces of a cell that outlines touch: a constrained Delaunay triangulation of the cell's
// corners, its diagonal and the outline items.
std::vector<Piece> triangulateCell(const DrapeGrid &g, int c, int r, const CellItem *items, size_t count,
                                   const std::vector<OutlineEdge> &row, const AreaRanking &ranking) {
    Vec2d sw{g.lines.xs[size_t(c)], g.lines.ys[size_t(r)]}, ne{g.lines.xs[size_t(c) + 1], g.lines.ys[size_t(r) + 1]};
    std::vector<Piece> pieces;
    try {
        using P = FastCdt::Point;
        std::optional<CutCell> cutCell = cutAtDiagonal(sw, ne, items, count);
        if (!cutCell) throw FastCdt::Intersection_of_constraints_exception();
        const CutCell &cut = *cutCell;
        FastCdt cdt;
        insertCorners(cdt, g, c, r);
        for (Vec2d p : cut.points) cdt.insert(P(p.x, p.y));
        for (size_t i = 1; i < cut.diagonal.size(); ++i) {
            cdt.insert_constraint(P(cut.diagonal[i - 1].x, cut.diagonal[i - 1].y),
                                  P(cut.diagonal[i].x, cut.diagonal[i].y));
        }
        for (const Segment &e : cut.segments) cdt.insert_constraint(P(e.first.x, e.first.y), P(e.second.x, e.second.y));
        collectPieces(cdt, g, c, r, row, ranking, pieces);
        return pieces;
    } catch (const FastCdt::Intersection_of_constraints_exception &) {
        pieces.clear();
    }
    using P = ExactCdt::Point;
    ExactCdt cdt;
    insertCorners(cdt, g, c, r);
    cdt.insert_constraint(P(sw.x, sw.y), P(ne.x, ne.y));
    for (size_t i = 0; i < count; ++i) {
        const CellItem &item = items[i];
        if (item.a == item.b) {
            cdt.insert(P(item.a.x, item.a.y));
        } else {
            cdt.insert_constraint(P(item.a.x, item.a.y), P(item.b.x, item.b.y));
        }
    }
    collectPieces(cdt, g, c, r, row, ranking, pieces);
    return pieces;
}

// The winning area of each cell of row r that no outline touches, from the crossings of the
// row's mid line: the area is the same all over such a cell.
std::vector<uint32_t> untouchedCellAreas(const DrapeGrid &g, int r, const std::vector<OutlineEdge> &row,
                                         const AreaRanking &ranking, size_t areaCount) {
    double y = 0.5 * (g.lines.ys[size_t(r)] + g.lines.ys[size_t(r) + 1]);
    std::vector<std::pair<double, uint32_t>> crossings;
    for (const OutlineEdge &e : row) {
        if ((e.a.y <= y) == (e.b.y <= y)) continue;
        crossings.emplace_back(e.a.x + (y - e.a.y) / (e.b.y - e.a.y) * (e.b.x - e.a.x), e.area);
    }
    std::sort(crossings.begin(), crossings.end());
    std::vector<uint8_t> inside(areaCount, 0);
    auto order = [&](uint32_t a, uint32_t b) { return ranking.better(a, b); };
    std::set<uint32_t, decltype(order)> insideAreas(order);
    std::vector<uint32_t> result(size_t(g.cellColumns));
    size_t next = 0;
    for (int c = 0; c < g.cellColumns; ++c) {
        double x = 0.5 * (g.lines.xs[size_t(c)] + g.lines.xs[size_t(c) + 1]);
        for (; next < crossings.size() && crossings[next].first < x; ++next) {
            uint32_t area = crossings[next].second;
            inside[area] ^= 1;
            if (inside[area]) insideAreas.insert(area);
            else insideAreas.erase(area);
        }
        result[size_t(c)] = insideAreas.empty() ? kNoArea : *insideAreas.begin();
    }
    return result;
}

struct PointHash {
    size_t operator()(const Vec2d &p) const {
        // + 0.0 makes −0 and +0, which compare equal, hash alike.
        uint64_t x = std::bit_cast<uint64_t>(p.x + 0.0), y = std::bit_cast<uint64_t>(p.y + 0.0);
        return size_t(x * 0x9E3779B97F4A7C15ull ^ (y + 0x632BE59BD9B4E019ull + (x << 6) + (x >> 2)));
    }
};

// Collects pieces into one mesh, one vertex per grid node and per outline point.
class TerrainBuilder {
  public:
    TerrainBuilder(const DrapeGrid &g, DrapedTerrain &out) :
        g_(g), out_(out), nodeVertices_(g.heights.heights.size(), kNoVertex) {
        plan_.reserve(out.mesh.positions.capacity());
    }

    void add(const Piece &piece) {
        std::array<uint32_t, 3> v;
        for (size_t k = 0; k < 3; ++k) v[k] = vertex(piece.corners[k]);
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return;  // two outline points closer than a double
        out_.mesh.indices.insert(out_.mesh.indices.end(), v.begin(), v.end());
        out_.triangleArea.push_back(piece.area);
    }
    void addPlainCell(int c, int r, uint32_t area) {
        auto corner = [&](int dc, int dr) {
            int64_t node = g_.nodeIndex(c + dc, r + dr);
            return PieceVertex{
                node, {g_.lines.xs[size_t(c + dc)], g_.lines.ys[size_t(r + dr)]}, g_.heights.heights[size_t(node)]};
        };
        PieceVertex sw = corner(0, 0), se = corner(1, 0), nw = corner(0, 1), ne = corner(1, 1);
        add({{sw, se, ne}, area});
        add({{sw, ne, nw}, area});
    }
    // Local xy in double, for the uvs.
    const std::vector<Vec2d> &planPositions() const { return plan_; }

  private:
    static constexpr uint32_t kNoVertex = ~0u;

    uint32_t vertex(const PieceVertex &p) {
        uint32_t *slot = nullptr;
        if (p.node >= 0) {
            slot = &nodeVertices_[size_t(p.node)];
        } else {
            auto [it, inserted] = others_.try_emplace(p.at, kNoVertex);
            slot = &it->second;
        }
        if (*slot == kNoVertex) {
            *slot = uint32_t(out_.mesh.positions.size());
            out_.mesh.positions.push_back({float(p.at.x), float(p.at.y), p.height});
            plan_.push_back(p.at);
        }
        return *slot;
    }

    const DrapeGrid &g_;
    DrapedTerrain &out_;
    std::vector<uint32_t> nodeVertices_;
    std::unordered_map<Vec2d, uint32_t, PointHash> others_;
    std::vector<Vec2d> plan_;
};

// The minimum of the grid's surface along a cut outline: on each edge (within one cell) at
// its ends and where it crosses the cell's diagonal. NaN when no part has data.
float outlineMinimum(const DrapeGrid &g, const std::vector<Vec2d> &ring) {
    float lowest = std::numeric_limits<float>::quiet_NaN();
    forEachEdge(ring, [&](Vec2d a, Vec2d b) {
        GridLines::CellSpan columns = g.lines.columnsHolding(std::min(a.x, b.x), std::max(a.x, b.x));
        GridLines::CellSpan rows = g.lines.rowsHolding(std::min(a.y, b.y), std::max(a.y, b.y));
        if (columns.count == 0 || rows.count == 0) return;
        int c = columns.first, r = rows.first;
        if (!g.cellHasData(c, r)) return;
        auto diagonal = [&](Vec2d p) {  // u − v: zero on the diagonal
            return (p.x - g.lines.xs[size_t(c)]) / (g.lines.xs[size_t(c) + 1] - g.lines.xs[size_t(c)]) -
                (p.y - g.lines.ys[size_t(r)]) / (g.lines.ys[size_t(r) + 1] - g.lines.ys[size_t(r)]);
        };
        double da = diagonal(a), db = diagonal(b);
        lowest = std::fmin(lowest, std::fmin(g.heightIn(c, r, a), g.heightIn(c, r, b)));
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            double t = da / (da - db);
            lowest = std::fmin(lowest, g.heightIn(c, r, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}));
        }
    });
    return lowest;
}

void flattenWater(const DrapeGrid &g, const std::vector<DrapeArea> &areas, const std::vector<std::vector<Vec2d>> &rings,
                  DrapedTerrain &terrain) {
    terrain.waterLevel.assign(areas.size(), std::numeric_limits<float>::quiet_NaN());
    for (size_t i = 0; i < areas.size(); ++i) {
        if (areas[i].landClass == LandClass::Water) terrain.waterLevel[i] = outlineMinimum(g, rings[i]);
    }
    std::vector<float> level(terrain.mesh.positions.size(), std::numeric_limits<float>::quiet_NaN());
    for (size_t t = 0; t < terrain.triangleArea.size(); ++t) {
        uint32_t area = terrain.triangleArea[t];
        if (area == kNoArea || std::isnan(terrain.waterLevel[area])) continue;
        for (size_t k = 0; k < 3; ++k) {
            float &l = level[terrain.mesh.indices[3 * t + k]];
            l = std::fmin(l, terrain.waterLevel[area]);
        }
    }
    for (size_t v = 0; v < level.size(); ++v) {
        if (!std::isnan(level[v])) terrain.mesh.positions[v].z = level[v];
    }
}

}  // namespace

int drapePriority(LandClass landClass) {
    switch (landClass) {
    case LandClass::CityStreet: return 11;
    case LandClass::Building: return 10;
    case LandClass::Water:
    case LandClass::River: return 9;
    case LandClass::Road:
    case LandClass::Path:
    case LandClass::Rail: return 8;
    case LandClass::Settlement: return 7;
    case LandClass::Park: return 6;
    case LandClass::Forest: return 5;
    case LandClass::Shrubs:
    case LandClass::TreeRow:
    case LandClass::Hedge: return 4;
    case LandClass::Farmland: return 3;
    case LandClass::Grassland: return 2;
    case LandClass::Other:
    case LandClass::Parcel: return 1;
    }
    return 1;
}

DrapedTerrain drapeAreas(const HeightGrid &grid, const LocalFrame &frame, const std::vector<DrapeArea> &areas,
                         const DrapeOptions &options) {
    DrapedTerrain terrain;
    if (!(options.textureTile > 0)) {
        throw InputError(FileLoc{}, fmt::format("the texture tile must be positive, not {}", options.textureTile));
    }
    if (grid.columns < 2 || grid.rows < 2) return terrain;
    DrapeGrid g{grid, gridLines(grid, frame), grid.columns - 1, grid.rows - 1};
    std::vector<std::vector<Vec2d>> rings = cutOutlines(areas, frame, g.lines);
    std::vector<std::vector<OutlineEdge>> rowEdges = edgesByRow(rings, g);
    std::vector<CellItem> items = itemsByCell(rings, g);
    AreaRanking ranking(areas);

    // The touched cells, each a run of items, triangulated in parallel.
    std::vector<size_t> runs;  // start of each cell's run in `items`
    for (size_t i = 0; i < items.size(); ++i) {
        if (i == 0 || items[i].cell != items[i - 1].cell) runs.push_back(i);
    }
    runs.push_back(items.size());
    std::vector<std::vector<Piece>> touched(runs.size() - 1);
    tbb::parallel_for(size_t(0), touched.size(), [&](size_t k) {
        size_t cell = items[runs[k]].cell;
        int c = int(cell % size_t(g.cellColumns)), r = int(cell / size_t(g.cellColumns));
        if (!g.cellHasData(c, r)) return;
        touched[k] = triangulateCell(g, c, r, &items[runs[k]], runs[k + 1] - runs[k], rowEdges[size_t(r)], ranking);
    });

    size_t pieceCount = 0;
    for (const std::vector<Piece> &pieces : touched) pieceCount += pieces.size();
    terrain.mesh.positions.reserve(grid.heights.size() + items.size());
    terrain.mesh.indices.reserve(3 * (2 * size_t(g.cellColumns) * size_t(g.cellRows) + pieceCount));
    terrain.triangleArea.reserve(terrain.mesh.indices.capacity() / 3);
    TerrainBuilder builder(g, terrain);
    size_t nextTouched = 0;
    for (int r = 0; r < g.cellRows; ++r) {
        std::vector<uint32_t> plainAreas = untouchedCellAreas(g, r, rowEdges[size_t(r)], ranking, areas.size());
        for (int c = 0; c < g.cellColumns; ++c) {
            size_t cell = g.cellIndex(c, r);
            if (nextTouched < touched.size() && items[runs[nextTouched]].cell == cell) {
                for (const Piece &piece : touched[nextTouched]) builder.add(piece);
                ++nextTouched;
            } else if (g.cellHasData(c, r)) {
                builder.addPlainCell(c, r, plainAreas[size_t(c)]);
            }
        }
    }

    flattenWater(g, areas, rings, terrain);
    Mesh &mesh = terrain.mesh;
    mesh.normals = areaWeightedNormals(mesh);
    mesh.uvs.reserve(mesh.positions.size());
    for (Vec2d p : builder.planPositions()) {
        mesh.uvs.push_back({float(p.x / options.textureTile), float(p.y / options.textureTile)});
    }
    mesh.triangleMaterials.assign(mesh.triangleCount(), 0);
    return terrain;
}

}  // namespace veduta
