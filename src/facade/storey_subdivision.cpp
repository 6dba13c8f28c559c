#include "facade/storey_subdivision.h"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/convex_hull_2.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>

#include "core/polygon_area.h"

namespace veduta {

namespace {

// Exact constructions: the crossings of subdivision segments (V'') and the Boolean operations
// of the storey features must meet exactly where they meet.
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = ExactKernel::Point_2;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;
using Traits = CGAL::Arr_segment_traits_2<ExactKernel>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kRelativeEpsilon = 1e-9;

Vec2d lerp(Vec2d p, Vec2d q, double t) { return p * (1 - t) + q * t; }
Vec2d toVec(const ExactPoint &p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

double extent(const std::vector<Vec2d> &ring) {
    double scale = 1;
    for (Vec2d p : ring) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
    return scale;
}

double distanceToSegment(Vec2d p, Vec2d a, Vec2d b) {
    Vec2d ab = b - a;
    double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(p - (a + ab * t));
}

bool onRing(Vec2d p, const std::vector<Vec2d> &ring, double eps) {
    for (size_t i = 0; i < ring.size(); ++i)
        if (distanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]) <= eps) return true;
    return false;
}

std::vector<Vec2d> convexHull(const std::vector<Vec2d> &points) {
    std::vector<Kernel::Point_2> in, out;
    for (Vec2d p : points) in.emplace_back(p.x, p.y);
    CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
    std::vector<Vec2d> hull;
    for (const Kernel::Point_2 &p : out) hull.push_back({p.x(), p.y()});
    return hull;
}

ExactPolygon toExact(const std::vector<Vec2d> &ring) {
    ExactPolygon polygon;
    for (Vec2d p : ring) polygon.push_back(ExactPoint(p.x, p.y));
    return polygon;
}

std::vector<Vec2d> ringOf(const ExactPolygon &polygon) {
    std::vector<Vec2d> ring;
    for (const ExactPoint &p : polygon.vertices()) ring.push_back(toVec(p));
    return ring;
}

// The polylines of the ring's edges whose flag is `wanted`, each a maximal run; a ring that is
// all `wanted` comes back closed (first point repeated).
std::vector<std::vector<Vec2d>> runsOf(const std::vector<Vec2d> &ring, const std::vector<bool> &flags, bool wanted) {
    size_t n = ring.size(), start = 0;
    while (start < n && flags[start] == flags[(start + n - 1) % n]) ++start;
    if (start == n) start = 0;
    std::vector<std::vector<Vec2d>> runs;
    for (size_t k = 0; k < n; ++k) {
        size_t i = (start + k) % n;
        if (flags[i] != wanted) continue;
        if (k == 0 || flags[(i + n - 1) % n] != wanted || runs.empty()) runs.push_back({ring[i]});
        runs.back().push_back(ring[(i + 1) % n]);
    }
    return runs;
}

// The ring's edges split at the points of `cuts` that lie inside them.
std::vector<Vec2d> splitAt(const std::vector<Vec2d> &ring, const std::vector<Vec2d> &cuts, double eps) {
    std::vector<Vec2d> split;
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2d a = ring[i], b = ring[(i + 1) % ring.size()];
        std::vector<std::pair<double, Vec2d>> inside;
        for (Vec2d c : cuts) {
            double t = dot(c - a, b - a) / dot(b - a, b - a);
            if (t > 0 && t < 1 && distanceToSegment(c, a, b) <= eps) inside.push_back({t, c});
        }
        std::sort(inside.begin(), inside.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
        split.push_back(a);
        for (const auto &cut : inside) split.push_back(cut.second);
    }
    return split;
}

std::vector<Vec2d> outlineRing(const FloorPlan &plan) {
    std::vector<Vec2d> ring;
    for (const WalkPiece &piece : plan.outline()) ring.push_back(piece.from);
    return ring;
}

std::vector<bool> edgesOnRing(const std::vector<Vec2d> &ring, const std::vector<Vec2d> &other, double eps) {
    std::vector<bool> flags;
    for (size_t i = 0; i < ring.size(); ++i)
        flags.push_back(onRing((ring[i] + ring[(i + 1) % ring.size()]) * 0.5, other, eps));
    return flags;
}

double exactArea(const std::vector<ExactPolygonWithHoles> &pieces) {
    double sum = 0;
    for (const ExactPolygonWithHoles &piece : pieces) {
        sum += CGAL::to_double(piece.outer_boundary().area());
        for (const ExactPolygon &hole : piece.holes()) sum += CGAL::to_double(hole.area());
    }
    return sum;
}

std::vector<Vec2d> subdivisionPositions(const std::vector<Vec2d> &outline, const std::vector<SubdivisionPoint> &points,
                                        const FileLoc &loc) {
    std::vector<Vec2d> positions;
    for (size_t i = 0; i < points.size(); ++i) {
        const SubdivisionPoint &p = points[i];
        if (p.edge < 0 || p.edge >= static_cast<int>(outline.size()))
            throw InputError(loc, fmt::format("subdivision point {}: the module has no edge {}", i, p.edge));
        if (!std::isfinite(p.t) || p.t < 0 || p.t >= 1)
            throw InputError(loc, fmt::format("subdivision point {}: t = {} is outside [0, 1)", i, p.t));
        positions.push_back(lerp(outline[p.edge], outline[(p.edge + 1) % outline.size()], p.t));
    }
    return positions;
}

// The module's boundary through every subdivision point on it, so that segments end exactly on
// it (a point e[t] computed in double is not exactly on the straight edge).
std::vector<Vec2d> boundaryThroughPoints(const std::vector<Vec2d> &outline, const std::vector<SubdivisionPoint> &points,
                                         const std::vector<Vec2d> &positions) {
    std::vector<Vec2d> ring;
    for (size_t e = 0; e < outline.size(); ++e) {
        std::vector<std::pair<double, Vec2d>> onEdge = {{0.0, outline[e]}};
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i].edge == static_cast<int>(e) && points[i].t > 0) onEdge.push_back({points[i].t, positions[i]});
        std::sort(onEdge.begin(), onEdge.end(), [](const auto &x, const auto &y) { return x.first < y.first; });
        for (size_t k = 0; k < onEdge.size(); ++k)
            if (k == 0 || onEdge[k].first != onEdge[k - 1].first) ring.push_back(onEdge[k].second);
    }
    return ring;
}

// The unions of connected sets of cells that are convex: area equal to the hull's.
std::vector<std::vector<int>> convexUnions(const std::vector<std::vector<Vec2d>> &cells,
                                           const std::vector<uint32_t> &neighbours, double scale) {
    int n = static_cast<int>(cells.size());
    std::vector<bool> seen(size_t{1} << n);
    std::vector<uint32_t> queue;
    for (int c = 0; c < n; ++c) {
        queue.push_back(uint32_t{1} << c);
        seen[uint32_t{1} << c] = true;
    }
    for (size_t q = 0; q < queue.size(); ++q) {
        uint32_t border = 0;
        for (int c = 0; c < n; ++c)
            if (queue[q] >> c & 1) border |= neighbours[c];
        border &= ~queue[q];
        for (int c = 0; c < n; ++c) {
            uint32_t grown = queue[q] | uint32_t{1} << c;
            if (!(border >> c & 1) || seen[grown]) continue;
            seen[grown] = true;
            queue.push_back(grown);
        }
    }
    std::sort(queue.begin(), queue.end(), [](uint32_t x, uint32_t y) {
        return std::popcount(x) != std::popcount(y) ? std::popcount(x) < std::popcount(y) : x < y;
    });
    std::vector<std::vector<int>> unions;
    for (uint32_t set : queue) {
        std::vector<int> members;
        std::vector<Vec2d> points;
        double sum = 0;
        for (int c = 0; c < n; ++c) {
            if (!(set >> c & 1)) continue;
            members.push_back(c);
            points.insert(points.end(), cells[c].begin(), cells[c].end());
            sum += signedArea(cells[c]);
        }
        if (signedArea(convexHull(points)) - sum <= kRelativeEpsilon * scale * scale) unions.push_back(members);
    }
    return unions;
}

}  // namespace

StoreySubdivision subdivideModule(const std::vector<Vec2d> &outline, const std::vector<SubdivisionPoint> &points,
                                  const std::vector<std::pair<int, int>> &segments, const FileLoc &loc) {
    std::vector<Kernel::Point_2> corners;
    for (Vec2d p : outline) corners.emplace_back(p.x, p.y);
    if (outline.size() < 3 || !CGAL::is_convex_2(corners.begin(), corners.end(), Kernel()) ||
        CGAL::orientation_2(corners.begin(), corners.end(), Kernel()) != CGAL::COUNTERCLOCKWISE)
        throw InputError(loc, "the subdivided module is not a convex counter-clockwise polygon");
    std::vector<Vec2d> positions = subdivisionPositions(outline, points, loc);
    std::vector<Vec2d> boundary = boundaryThroughPoints(outline, points, positions);
    double eps = kRelativeEpsilon * extent(outline);
    std::vector<Traits::Segment_2> pieces;
    for (size_t i = 0; i < boundary.size(); ++i) {
        Vec2d a = boundary[i], b = boundary[(i + 1) % boundary.size()];
        pieces.emplace_back(ExactPoint(a.x, a.y), ExactPoint(b.x, b.y));
    }
    for (size_t s = 0; s < segments.size(); ++s) {
        auto [i, j] = segments[s];
        if (i < 0 || j < 0 || i >= static_cast<int>(points.size()) || j >= static_cast<int>(points.size()))
            throw InputError(loc,
                             fmt::format("subdivision segment {}: a point index of ({}, {}) is out of range", s, i, j));
        Vec2d a = positions[i], b = positions[j];
        if (length(b - a) <= eps) throw InputError(loc, fmt::format("subdivision segment {}: its ends coincide", s));
        if (onRing((a + b) * 0.5, outline, eps))
            throw InputError(loc, fmt::format("subdivision segment {}: it runs along the module's edge", s));
        pieces.emplace_back(ExactPoint(a.x, a.y), ExactPoint(b.x, b.y));
    }
    Arrangement arrangement;
    CGAL::insert(arrangement, pieces.begin(), pieces.end());

    StoreySubdivision result;
    std::map<Arrangement::Face_const_handle, int> cellOf;
    for (auto face = arrangement.faces_begin(); face != arrangement.faces_end(); ++face) {
        if (face->is_unbounded()) continue;
        if (static_cast<int>(result.cells.size()) == kMaxSubdivisionCells)
            throw InputError(loc, fmt::format("the subdivision makes more than {} cells", kMaxSubdivisionCells));
        std::vector<Vec2d> cell;
        auto edge = face->outer_ccb(), first = edge;
        do cell.push_back(toVec(edge->source()->point()));
        while (++edge != first);
        cellOf[face] = static_cast<int>(result.cells.size());
        result.cells.push_back(cell);
    }
    std::vector<uint32_t> neighbours(result.cells.size());
    for (auto edge = arrangement.edges_begin(); edge != arrangement.edges_end(); ++edge) {
        auto f = edge->face(), g = edge->twin()->face();
        if (f->is_unbounded() || g->is_unbounded()) continue;
        neighbours[cellOf[f]] |= uint32_t{1} << cellOf[g];
        neighbours[cellOf[g]] |= uint32_t{1} << cellOf[f];
    }
    result.candidates = convexUnions(result.cells, neighbours, extent(outline));
    return result;
}

std::vector<Vec2d> candidateOutline(const StoreySubdivision &subdivision, const std::vector<int> &candidate) {
    std::vector<Vec2d> points;
    for (int c : candidate) points.insert(points.end(), subdivision.cells[c].begin(), subdivision.cells[c].end());
    return convexHull(points);
}

FloorPlan repeatStorey(const FloorPlan &storey) {
    return FloorPlan(storey.modules(), storey.kkConnections(), storey.ppConnections());
}

StoreyFeatures storeyFeatures(const FloorPlan &lower, const FloorPlan &upper) {
    std::vector<Vec2d> lowerRing = outlineRing(lower), upperRing = outlineRing(upper);
    double eps = kRelativeEpsilon * std::max(extent(lowerRing), extent(upperRing));
    StoreyFeatures features;
    std::vector<ExactPolygonWithHoles> free;
    CGAL::difference(toExact(lowerRing), toExact(upperRing), std::back_inserter(free));
    for (const ExactPolygonWithHoles &area : free) {
        std::vector<std::vector<Vec2d>> rings = {ringOf(area.outer_boundary())};
        for (const ExactPolygon &hole : area.holes()) rings.push_back(ringOf(hole));
        for (const std::vector<Vec2d> &ring : rings) {
            std::vector<bool> outer = edgesOnRing(ring, lowerRing, eps);
            for (auto &run : runsOf(ring, outer, true)) features.freeOuterEdges.push_back(run);
            for (auto &run : runsOf(ring, outer, false)) features.innerEdges.push_back(run);
        }
    }
    std::vector<Vec2d> upperSplit = splitAt(upperRing, lowerRing, eps);
    for (auto &run : runsOf(upperSplit, edgesOnRing(upperSplit, lowerRing, eps), true)) features.seams.push_back(run);
    ExactPolygon lowerPolygon = toExact(lowerRing);
    for (size_t k = 0; k < upper.kkConnections().size(); ++k) {
        const std::vector<Vec2d> &docked = upper.modules()[upper.kkConnections()[k].docked].outline;
        std::vector<ExactPolygonWithHoles> inside;
        CGAL::intersection(toExact(docked), lowerPolygon, std::back_inserter(inside));
        bool external = signedArea(docked) - exactArea(inside) > kRelativeEpsilon * signedArea(docked);
        (external ? features.externalConnections : features.internalConnections).push_back(static_cast<int>(k));
    }
    return features;
}

}  // namespace veduta
