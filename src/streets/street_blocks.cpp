#include "streets/street_blocks.h"

#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

namespace veduta {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
constexpr size_t kNoFace = std::numeric_limits<size_t>::max();
constexpr double kLargestCoordinate = 1e100, kSmallestCoordinate = 1e-100;

using Cycle = std::vector<uint32_t>;

// ---- The input, cleaned alike for both methods ----

void checkInput(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges) {
    if (points.size() > kMaxBlockGraphSize || edges.size() > kMaxBlockGraphSize)
        throw std::invalid_argument("street blocks: more than " + std::to_string(kMaxBlockGraphSize) +
                                    " points or edges");
    for (const PlanarPoint &p : points) {
        for (double c : {p.x, p.y}) {
            double size = std::abs(c);
            if (!(size <= kLargestCoordinate) || (c != 0 && size < kSmallestCoordinate))
                throw std::invalid_argument(
                    "street blocks: a coordinate is not finite, or beyond 1e100 or below "
                    "1e-100 in magnitude");
        }
    }
    for (const auto &[a, b] : edges) {
        if (a >= points.size() || b >= points.size())
            throw std::invalid_argument("street blocks: an edge index has no point");
    }
}

bool lexicographicLess(const PlanarPoint &a, const PlanarPoint &b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
bool samePlace(const PlanarPoint &a, const PlanarPoint &b) { return a.x == b.x && a.y == b.y; }

// The edges both methods work on: each point stands for the copies of its coordinates with
// larger indices, an edge is (smaller, larger) index, and each one is there once.
struct CleanGraph {
    std::vector<PlanarEdge> edges;  // sorted
    std::vector<uint32_t> byPlace;  // the points edges end at, in lexicographic order
    size_t ignoredEdges = 0, ignoredPoints = 0;
};

std::vector<uint32_t> firstAtSamePlace(std::span<const PlanarPoint> points) {
    std::vector<uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::ranges::sort(order, [&](uint32_t a, uint32_t b) {
        if (lexicographicLess(points[a], points[b])) return true;
        return samePlace(points[a], points[b]) && a < b;
    });
    std::vector<uint32_t> first(points.size());
    for (size_t i = 0; i < order.size(); ++i) {
        bool copy = i > 0 && samePlace(points[order[i]], points[order[i - 1]]);
        first[order[i]] = copy ? first[order[i - 1]] : order[i];
    }
    return first;
}

CleanGraph cleanGraph(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges) {
    checkInput(points, edges);
    std::vector<uint32_t> first = firstAtSamePlace(points);
    CleanGraph graph;
    for (const auto &[a, b] : edges) {
        uint32_t u = first[a], v = first[b];
        if (u != v) graph.edges.emplace_back(std::min(u, v), std::max(u, v));
    }
    std::ranges::sort(graph.edges);
    graph.edges.erase(std::unique(graph.edges.begin(), graph.edges.end()), graph.edges.end());
    graph.ignoredEdges = edges.size() - graph.edges.size();
    for (const auto &[a, b] : graph.edges) graph.byPlace.insert(graph.byPlace.end(), {a, b});
    std::ranges::sort(graph.byPlace, [&](uint32_t a, uint32_t b) { return lexicographicLess(points[a], points[b]); });
    graph.byPlace.erase(std::unique(graph.byPlace.begin(), graph.byPlace.end()), graph.byPlace.end());
    graph.ignoredPoints = points.size() - graph.byPlace.size();
    return graph;
}

// ---- Boundary walks to blocks, alike for both methods ----

// Cuts closed walks around a face (the points they pass, in order) into simple cycles: wherever
// a walk comes back to a point still on its path, the path since then is a cycle. The cycles of
// two points are an edge walked there and back, an antenna (a dead end, or a bridge between
// two parts of the boundary): they are dropped.
class CycleCutter {
  public:
    explicit CycleCutter(size_t points) : placeOnPath_(points, kNone) {}

    std::vector<Cycle> cut(std::span<const uint32_t> walk) {
        std::vector<Cycle> cycles;
        for (uint32_t point : walk) visit(point, cycles);
        visit(walk.front(), cycles);
        backTo(0);
        return cycles;
    }

  private:
    void visit(uint32_t point, std::vector<Cycle> &cycles) {
        uint32_t place = placeOnPath_[point];
        if (place == kNone) {
            placeOnPath_[point] = uint32_t(path_.size());
            path_.push_back(point);
            return;
        }
        if (path_.size() - place > 2) cycles.emplace_back(path_.begin() + place, path_.end());
        backTo(place + 1);
    }

    void backTo(size_t length) {
        for (size_t i = length; i < path_.size(); ++i) placeOnPath_[path_[i]] = kNone;
        path_.resize(length);
    }

    std::vector<uint32_t> placeOnPath_;
    std::vector<uint32_t> path_;
};

// Whether a face's cycles pass a point twice: a face that touches itself, not a simple polygon
// with disjoint holes (the thesis' cycle passes no node twice, L780–782).
bool pinched(const std::vector<Cycle> &cycles) {
    std::vector<uint32_t> all;
    for (const Cycle &cycle : cycles) all.insert(all.end(), cycle.begin(), cycle.end());
    std::ranges::sort(all);
    return std::adjacent_find(all.begin(), all.end()) != all.end();
}

// The place in the cycle of its lexicographically smallest point: the polygon turns there the
// way it runs, so one exact orientation there gives the orientation of a simple polygon.
size_t lowestCorner(std::span<const PlanarPoint> points, const Cycle &cycle) {
    auto lowest = std::ranges::min_element(
        cycle, [&](uint32_t a, uint32_t b) { return lexicographicLess(points[a], points[b]); });
    return size_t(lowest - cycle.begin());
}

Cycle startingAtSmallest(Cycle cycle) {
    // Not ranges::rotate: clang 14 with libstdc++ 12 (the fuzz build) cannot compile it.
    std::rotate(cycle.begin(), std::ranges::min_element(cycle), cycle.end());
    return cycle;
}

// a·b − c·d with one rounding in all (Kahan): a sliver's area is not lost to cancellation.
double differenceOfProducts(double a, double b, double c, double d) {
    double cd = c * d;
    return std::fma(a, b, -cd) + std::fma(-c, d, cd);
}

// Twice the signed area, positive counter-clockwise; relative to the first point, which keeps
// the products small.
double twiceSignedArea(std::span<const PlanarPoint> points, const Cycle &cycle) {
    const PlanarPoint &origin = points[cycle.front()];
    double sum = 0;
    for (size_t i = 1; i + 1 < cycle.size(); ++i) {
        const PlanarPoint &a = points[cycle[i]], &b = points[cycle[i + 1]];
        sum += differenceOfProducts(a.x - origin.x, b.y - origin.y, a.y - origin.y, b.x - origin.x);
    }
    return sum;
}

// A face's cycles as a block, or nothing when they do not make a simple polygon with disjoint
// holes. `ccw` says which of them run counter-clockwise: the boundary. A face has exactly one,
// even where it touches itself (its face lies inside it and outside the others); more or none
// come only from edges that cross.
std::optional<StreetBlock> blockOf(std::span<const PlanarPoint> points, const std::vector<Cycle> &cycles,
                                   const std::vector<bool> &ccw) {
    if (pinched(cycles) || std::ranges::count(ccw, true) != 1) return std::nullopt;
    StreetBlock block;
    for (size_t i = 0; i < cycles.size(); ++i) {
        if (ccw[i]) block.boundary = startingAtSmallest(cycles[i]);
        else block.holes.push_back(startingAtSmallest(cycles[i]));
    }
    std::ranges::sort(block.holes);
    double twiceArea = twiceSignedArea(points, block.boundary);
    for (const Cycle &hole : block.holes) twiceArea += twiceSignedArea(points, hole);
    block.area = twiceArea / 2;
    return block;
}

// Adds a face's block to the result, or counts it as not simple.
void addFace(std::span<const PlanarPoint> points, const std::vector<Cycle> &cycles, const std::vector<bool> &ccw,
             BlockResult &result) {
    if (std::optional<StreetBlock> block = blockOf(points, cycles, ccw)) result.blocks.push_back(std::move(*block));
    else ++result.nonSimpleFaces;
}

BlockResult startResult(const CleanGraph &graph) {
    BlockResult result;
    result.ignoredEdges = graph.ignoredEdges;
    result.ignoredPoints = graph.ignoredPoints;
    return result;
}

// ---- The face walk's exact orientation (no CGAL) ----

// a + b == sum + error exactly (Knuth's TwoSum).
std::pair<double, double> twoSum(double a, double b) {
    double sum = a + b;
    double bPart = sum - a, aPart = sum - bPart;
    return {sum, (a - aPart) + (b - bPart)};
}

// a · b == product + error exactly, barring underflow (which the coordinate limits rule out).
std::pair<double, double> twoProduct(double a, double b) {
    double product = a * b;
    return {product, std::fma(a, b, -product)};
}

// The sum of the 16 exact terms of (b − a) × (c − a) as a nonoverlapping expansion, smallest
// component first (Shewchuk 1997, Grow-Expansion); its largest nonzero component has the sum's
// sign.
int exactOrientation(const PlanarPoint &a, const PlanarPoint &b, const PlanarPoint &c) {
    auto [bx, bxError] = twoSum(b.x, -a.x);
    auto [by, byError] = twoSum(b.y, -a.y);
    auto [cx, cxError] = twoSum(c.x, -a.x);
    auto [cy, cyError] = twoSum(c.y, -a.y);
    std::array<double, 32> expansion{};
    size_t size = 0;
    auto add = [&](double value) {
        for (size_t i = 0; i < size; ++i) std::tie(value, expansion[i]) = twoSum(value, expansion[i]);
        expansion[size++] = value;
    };
    for (double u : {bx, bxError}) {
        for (double v : {cy, cyError}) {
            auto [product, error] = twoProduct(u, v);
            add(product);
            add(error);
        }
    }
    for (double u : {by, byError}) {
        for (double v : {cx, cxError}) {
            auto [product, error] = twoProduct(u, v);
            add(-product);
            add(-error);
        }
    }
    for (size_t i = size; i-- > 0;) {
        if (expansion[i] != 0) return expansion[i] > 0 ? 1 : -1;
    }
    return 0;
}

// The sign of (b − a) × (c − a), exact: +1 when c lies left of a→b. The floating-point value
// decides when it is farther from 0 than its error can be (Shewchuk's bound for orient2d).
int orientation(const PlanarPoint &a, const PlanarPoint &b, const PlanarPoint &c) {
    constexpr double kEpsilon = std::numeric_limits<double>::epsilon() / 2;
    constexpr double kBound = (3 + 16 * kEpsilon) * kEpsilon;
    double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
    double value = left - right, bound = kBound * (std::abs(left) + std::abs(right));
    if (value > bound) return 1;
    if (value < -bound) return -1;
    return exactOrientation(a, b, c);
}

bool counterClockwiseByWalk(std::span<const PlanarPoint> points, const Cycle &cycle) {
    size_t i = lowestCorner(points, cycle), n = cycle.size();
    return orientation(points[cycle[(i + n - 1) % n]], points[cycle[i]], points[cycle[(i + 1) % n]]) > 0;
}

// Whether point p lies inside the cycle; false when p is one of its points (by the input's
// promise nothing else of the graph lies on it). Counts the crossings of the ray from p towards
// +x, each decided by an exact orientation.
bool encloses(std::span<const PlanarPoint> points, const Cycle &cycle, uint32_t p) {
    const PlanarPoint &at = points[p];
    bool inside = false;
    for (size_t i = 0; i < cycle.size(); ++i) {
        uint32_t a = cycle[i], b = cycle[(i + 1) % cycle.size()];
        if (a == p) return false;
        bool aAbove = points[a].y > at.y, bAbove = points[b].y > at.y;
        if (aAbove == bAbove) continue;
        int side = orientation(points[a], points[b], at);
        if (bAbove ? side > 0 : side < 0) inside = !inside;
    }
    return inside;
}

// ---- The face walk ----

// Each point's outgoing half-edges in counter-clockwise order from +x.
struct HalfEdges {
    std::vector<uint32_t> begin;  // point v's half-edges are [begin[v], begin[v + 1])
    std::vector<uint32_t> from, to, twin;
};

// Whether the direction from `at` to p lies in [0, π) from +x: the half-plane of a robust angle
// order (exact: the sign of a difference of doubles is that of the exact difference).
bool upperHalf(const PlanarPoint &at, const PlanarPoint &p) { return p.y > at.y || (p.y == at.y && p.x > at.x); }

// The angle order around a point: by half-plane, then by an exact orientation; directions that
// coincide (overlapping edges, outside the input's promise) by index, to keep the order strict.
bool angleLess(std::span<const PlanarPoint> points, uint32_t at, uint32_t a, uint32_t b) {
    bool aUpper = upperHalf(points[at], points[a]), bUpper = upperHalf(points[at], points[b]);
    if (aUpper != bUpper) return aUpper;
    int turn = orientation(points[at], points[a], points[b]);
    return turn != 0 ? turn > 0 : a < b;
}

HalfEdges halfEdges(std::span<const PlanarPoint> points, const std::vector<PlanarEdge> &edges) {
    HalfEdges graph;
    graph.begin.assign(points.size() + 1, 0);
    for (const auto &[a, b] : edges) {
        ++graph.begin[a + 1];
        ++graph.begin[b + 1];
    }
    std::partial_sum(graph.begin.begin(), graph.begin.end(), graph.begin.begin());
    // Half-edge 2k runs along edge k, 2k + 1 back; `slots` lists them by their place.
    std::vector<uint32_t> slots(2 * edges.size()), next(graph.begin.begin(), graph.begin.end() - 1);
    for (uint32_t k = 0; k < edges.size(); ++k) {
        slots[next[edges[k].first]++] = 2 * k;
        slots[next[edges[k].second]++] = 2 * k + 1;
    }
    auto source = [&](uint32_t h) { return h % 2 == 0 ? edges[h / 2].first : edges[h / 2].second; };
    auto target = [&](uint32_t h) { return h % 2 == 0 ? edges[h / 2].second : edges[h / 2].first; };
    for (uint32_t v = 0; v < points.size(); ++v) {
        std::sort(slots.begin() + graph.begin[v], slots.begin() + graph.begin[v + 1],
                  [&](uint32_t g, uint32_t h) { return angleLess(points, v, target(g), target(h)); });
    }
    std::vector<uint32_t> placeOf(slots.size());
    for (uint32_t place = 0; place < slots.size(); ++place) placeOf[slots[place]] = place;
    graph.from.resize(slots.size());
    graph.to.resize(slots.size());
    graph.twin.resize(slots.size());
    for (uint32_t place = 0; place < slots.size(); ++place) {
        graph.from[place] = source(slots[place]);
        graph.to[place] = target(slots[place]);
        graph.twin[place] = placeOf[slots[place] ^ 1];
    }
    return graph;
}

// The half-edge after h on the face to h's left: at h's end, the next one clockwise from the way
// back (the thesis' outer path, §4.3.2, without atan2: the half-edges are already in angle order).
uint32_t nextOnFace(const HalfEdges &graph, uint32_t h) {
    uint32_t back = graph.twin[h], v = graph.to[h];
    return back == graph.begin[v] ? graph.begin[v + 1] - 1 : back - 1;
}

// Every closed walk: the points it passes, each walk tracing one face boundary with the face on
// its left.
std::vector<std::vector<uint32_t>> faceWalks(const HalfEdges &graph) {
    std::vector<std::vector<uint32_t>> walks;
    std::vector<bool> walked(graph.to.size(), false);
    for (uint32_t start = 0; start < graph.to.size(); ++start) {
        if (walked[start]) continue;
        std::vector<uint32_t> &walk = walks.emplace_back();
        for (uint32_t h = start; !walked[h]; h = nextOnFace(graph, h)) {
            walked[h] = true;
            walk.push_back(graph.from[h]);
        }
    }
    return walks;
}

struct Box {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;
    bool contains(const PlanarPoint &p) const { return minX <= p.x && p.x <= maxX && minY <= p.y && p.y <= maxY; }
};

Box boxOf(std::span<const PlanarPoint> points, const Cycle &cycle) {
    const PlanarPoint &first = points[cycle.front()];
    Box box{first.x, first.y, first.x, first.y};
    for (uint32_t i : cycle) {
        box.minX = std::min(box.minX, points[i].x);
        box.minY = std::min(box.minY, points[i].y);
        box.maxX = std::max(box.maxX, points[i].x);
        box.maxY = std::max(box.maxY, points[i].y);
    }
    return box;
}

// A bounded face found by the walk: the cycles of its own walk and, once placed, of the walks
// around what lies inside it.
struct WalkFace {
    std::vector<Cycle> cycles;
    std::vector<bool> ccw;
    size_t boundary = 0;  // its counter-clockwise cycle (the first, where crossing edges give more)
    Box box;
};

// Whether `inner`, nested with `outer` one way or the other, is the inner one: a point of it that
// is not one of outer's lies inside outer.
bool liesInside(std::span<const PlanarPoint> points, const Cycle &inner, const Cycle &outer) {
    for (uint32_t p : inner) {
        if (std::ranges::find(outer, p) == outer.end()) return encloses(points, outer, p);
    }
    return false;
}

// The face whose boundary encloses point p most closely, or kNoFace: p lies in the unbounded face.
// The boundaries that enclose p are nested (cycles of a plane graph do not cross), so the
// innermost is the one inside all others.
size_t enclosingFace(std::span<const PlanarPoint> points, const std::vector<WalkFace> &faces, uint32_t p) {
    size_t best = kNoFace;
    for (size_t f = 0; f < faces.size(); ++f) {
        const Cycle &boundary = faces[f].cycles[faces[f].boundary];
        if (!faces[f].box.contains(points[p]) || !encloses(points, boundary, p)) continue;
        if (best == kNoFace || liesInside(points, boundary, faces[best].cycles[faces[best].boundary])) best = f;
    }
    return best;
}

// ---- The arrangement ----

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Arr_segment_traits_2<Kernel>;
// Each vertex holds the index of its input point, or kNone for a point the input does not have.
using Arrangement = CGAL::Arrangement_2<Traits, CGAL::Arr_extended_dcel<Traits, uint32_t, bool, bool>>;

Kernel::Point_2 exactPoint(const PlanarPoint &p) { return {p.x, p.y}; }

// A coordinate rounded to a double: where it is one, its interval approximation is that double
// alone, and only the others need the exact value.
double rounded(const Kernel::FT &coordinate) {
    const auto &approximation = coordinate.approx();
    return approximation.is_point() ? approximation.inf() : CGAL::to_double(coordinate.exact());
}

// The index of the input point at p, or kNone. An input point is a pair of doubles, so the
// coordinates rounded find it, and an exact comparison makes sure.
uint32_t inputPointAt(std::span<const PlanarPoint> points, const CleanGraph &graph, const Kernel::Point_2 &p) {
    PlanarPoint at{rounded(p.x()), rounded(p.y())};
    auto place = std::ranges::lower_bound(graph.byPlace, at, lexicographicLess, [&](uint32_t i) { return points[i]; });
    if (place == graph.byPlace.end() || exactPoint(points[*place]) != p) return kNone;
    return *place;
}

Arrangement arrangementOf(std::span<const PlanarPoint> points, const CleanGraph &graph) {
    std::vector<Traits::Curve_2> segments;
    segments.reserve(graph.edges.size());
    for (const auto &[a, b] : graph.edges) segments.emplace_back(exactPoint(points[a]), exactPoint(points[b]));
    Arrangement arrangement;
    // The general insertion: edges that cross despite the promise give vertices of their own.
    CGAL::insert(arrangement, segments.begin(), segments.end());
    for (auto vertex = arrangement.vertices_begin(); vertex != arrangement.vertices_end(); ++vertex)
        vertex->set_data(inputPointAt(points, graph, vertex->point()));
    return arrangement;
}

bool isInputEdge(const CleanGraph &graph, Arrangement::Halfedge_const_handle h) {
    uint32_t a = h->source()->data(), b = h->target()->data();
    if (a == kNone || b == kNone) return false;
    return std::ranges::binary_search(graph.edges, PlanarEdge(std::min(a, b), std::max(a, b)));
}

// The points a boundary of the face passes, in order, or nothing when one of its edges is not
// an input edge.
std::optional<std::vector<uint32_t>> walkOf(const CleanGraph &graph, Arrangement::Ccb_halfedge_const_circulator ccb) {
    std::vector<uint32_t> walk;
    auto h = ccb;
    do {
        if (!isInputEdge(graph, h)) return std::nullopt;
        walk.push_back(h->source()->data());
    } while (++h != ccb);
    return walk;
}

// All cycles of a bounded face: its outer boundary's, then its inner boundaries' (CGAL walks
// both with the face on the left, so inner ones run clockwise), or nothing when it has an edge
// that is not an input edge.
std::optional<std::vector<Cycle>> faceCycles(const CleanGraph &graph, Arrangement::Face_const_handle face,
                                             CycleCutter &cutter) {
    std::vector<Arrangement::Ccb_halfedge_const_circulator> boundaries{face->outer_ccb()};
    boundaries.insert(boundaries.end(), face->inner_ccbs_begin(), face->inner_ccbs_end());
    std::vector<Cycle> cycles;
    for (auto ccb : boundaries) {
        std::optional<std::vector<uint32_t>> walk = walkOf(graph, ccb);
        if (!walk) return std::nullopt;
        for (Cycle &cycle : cutter.cut(*walk)) cycles.push_back(std::move(cycle));
    }
    return cycles;
}

bool counterClockwiseByKernel(std::span<const PlanarPoint> points, const Cycle &cycle) {
    size_t i = lowestCorner(points, cycle), n = cycle.size();
    return CGAL::orientation(exactPoint(points[cycle[(i + n - 1) % n]]), exactPoint(points[cycle[i]]),
                             exactPoint(points[cycle[(i + 1) % n]])) == CGAL::LEFT_TURN;
}

void finish(BlockResult &result) { std::ranges::sort(result.blocks, {}, &StreetBlock::boundary); }

}  // namespace

BlockResult blocksByArrangement(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges) {
    CleanGraph graph = cleanGraph(points, edges);
    BlockResult result = startResult(graph);
    const Arrangement arrangement = arrangementOf(points, graph);
    for (auto edge = arrangement.edges_begin(); edge != arrangement.edges_end(); ++edge) {
        if (!isInputEdge(graph, edge)) ++result.unmatchedEdges;
    }
    CycleCutter cutter(points.size());
    for (auto face = arrangement.faces_begin(); face != arrangement.faces_end(); ++face) {
        if (face->is_unbounded()) continue;
        std::optional<std::vector<Cycle>> cycles = faceCycles(graph, face, cutter);
        if (!cycles) {
            ++result.invalidFaces;
            continue;
        }
        std::vector<bool> ccw;
        for (const Cycle &cycle : *cycles) ccw.push_back(counterClockwiseByKernel(points, cycle));
        addFace(points, *cycles, ccw, result);
    }
    finish(result);
    return result;
}

BlockResult blocksByFaceWalk(std::span<const PlanarPoint> points, std::span<const PlanarEdge> edges) {
    CleanGraph graph = cleanGraph(points, edges);
    BlockResult result = startResult(graph);
    CycleCutter cutter(points.size());
    // A walk with a counter-clockwise cycle goes round a bounded face (positive area); the others
    // go round a connected part of the graph from outside, as a hole of the face around it.
    std::vector<WalkFace> faces;
    std::vector<std::vector<Cycle>> inner;
    for (const std::vector<uint32_t> &walk : faceWalks(halfEdges(points, graph.edges))) {
        WalkFace face;
        face.cycles = cutter.cut(walk);
        for (const Cycle &cycle : face.cycles) face.ccw.push_back(counterClockwiseByWalk(points, cycle));
        auto boundary = std::ranges::find(face.ccw, true);
        if (boundary == face.ccw.end()) {
            if (!face.cycles.empty()) inner.push_back(std::move(face.cycles));
            continue;
        }
        face.boundary = size_t(boundary - face.ccw.begin());
        face.box = boxOf(points, face.cycles[face.boundary]);
        faces.push_back(std::move(face));
    }
    // A part's points all lie in one face, so one of them tells which.
    for (std::vector<Cycle> &part : inner) {
        size_t f = enclosingFace(points, faces, part.front().front());
        if (f == kNoFace) continue;
        for (Cycle &hole : part) {
            faces[f].cycles.push_back(std::move(hole));
            faces[f].ccw.push_back(false);
        }
    }
    for (const WalkFace &face : faces) addFace(points, face.cycles, face.ccw, result);
    finish(result);
    return result;
}

}  // namespace veduta
