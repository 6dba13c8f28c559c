#include "facade/module_partition.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/partition_2.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <map>
#include <utility>

#include "core/check.h"
#include "core/polygon_area.h"

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using PartitionTraits = CGAL::Partition_traits_2<Kernel>;
using PartitionPolygon = PartitionTraits::Polygon_2;

Point toPoint(Vec2d p) { return {p.x, p.y}; }

std::vector<Vec2d> withoutRepeats(const std::vector<Vec2d> &ring) {
    std::vector<Vec2d> out;
    for (Vec2d p : ring)
        if (out.empty() || !(out.back() == p)) out.push_back(p);
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    return out;
}

// Drops vertices on the line through their neighbours (exact predicate), until none is left.
std::vector<Vec2d> withoutCollinear(std::vector<Vec2d> ring) {
    for (bool dropped = true; dropped && ring.size() >= 3;) {
        dropped = false;
        for (size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
            size_t n = ring.size();
            if (!CGAL::collinear(toPoint(ring[(i + n - 1) % n]), toPoint(ring[i]), toPoint(ring[(i + 1) % n])))
                continue;
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            dropped = true;
        }
    }
    return ring;
}

std::vector<std::vector<Vec2d>> convexPieces(const std::vector<Vec2d> &ring) {
    PartitionPolygon polygon;
    for (Vec2d p : ring) polygon.push_back(toPoint(p));
    std::list<PartitionPolygon> pieces;
    if (ring.size() <= kOptimalPartitionMaxVertices) {
        CGAL::optimal_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(pieces));
    } else {
        CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(pieces));
    }
    std::vector<std::vector<Vec2d>> result;
    for (const PartitionPolygon &piece : pieces) {
        std::vector<Vec2d> outline;
        for (auto v = piece.vertices_begin(); v != piece.vertices_end(); ++v) outline.push_back({v->x(), v->y()});
        result.push_back(outline);
    }
    return result;
}

using EdgeKey = std::pair<std::pair<double, double>, std::pair<double, double>>;
EdgeKey edgeKey(Vec2d from, Vec2d to) { return {{from.x, from.y}, {to.x, to.y}}; }

// KK docks along a breadth-first tree from the largest piece: each piece docks its edge onto
// the reversed, identical edge of the piece that reached it (the dual graph of a partition by
// diagonals is a tree).
std::vector<KkConnection> docksFromRoot(const std::vector<std::vector<Vec2d>> &pieces, int root) {
    std::map<EdgeKey, std::pair<int, int>> edgeOwner;
    for (size_t m = 0; m < pieces.size(); ++m)
        for (size_t i = 0; i < pieces[m].size(); ++i)
            edgeOwner[edgeKey(pieces[m][i], pieces[m][(i + 1) % pieces[m].size()])] = {static_cast<int>(m),
                                                                                       static_cast<int>(i)};
    std::vector<KkConnection> docks;
    std::vector<bool> reached(pieces.size());
    std::vector<int> queue = {root};
    reached[root] = true;
    for (size_t q = 0; q < queue.size(); ++q) {
        const std::vector<Vec2d> &outline = pieces[queue[q]];
        for (size_t i = 0; i < outline.size(); ++i) {
            auto twin = edgeOwner.find(edgeKey(outline[(i + 1) % outline.size()], outline[i]));
            if (twin == edgeOwner.end() || reached[twin->second.first]) continue;
            auto [docked, dockedEdge] = twin->second;
            docks.push_back({false, queue[q], static_cast<int>(i), docked, dockedEdge, 0, 1, {}});
            reached[docked] = true;
            queue.push_back(docked);
        }
    }
    VEDUTA_CHECK(queue.size() == pieces.size(), "convex partition pieces do not share whole edges");
    return docks;
}

}  // namespace

std::vector<Vec2d> cleanFootprint(const std::vector<Vec2d> &footprint, const FileLoc &loc) {
    for (Vec2d p : footprint)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError(loc, "a footprint vertex is not finite");
    std::vector<Vec2d> ring = withoutCollinear(withoutRepeats(footprint));
    if (ring.size() < 3)
        throw InputError(loc,
                         fmt::format("the footprint has {} vertices that are not collinear, it needs 3", ring.size()));
    std::vector<Point> points;
    for (Vec2d p : ring) points.push_back(toPoint(p));
    if (!CGAL::is_simple_2(points.begin(), points.end(), Kernel()))
        throw InputError(loc, "the footprint crosses itself");
    if (CGAL::orientation_2(points.begin(), points.end(), Kernel()) == CGAL::CLOCKWISE)
        std::reverse(ring.begin(), ring.end());
    return ring;
}

FloorPlan partitionFootprint(const std::vector<Vec2d> &footprint, const FloorPlanModule &prototype,
                             const FileLoc &loc) {
    std::vector<std::vector<Vec2d>> pieces = convexPieces(cleanFootprint(footprint, loc));
    int root = 0;
    for (size_t m = 1; m < pieces.size(); ++m)
        if (signedArea(pieces[m]) > signedArea(pieces[root])) root = static_cast<int>(m);
    std::vector<KkConnection> docks = docksFromRoot(pieces, root);
    std::vector<FloorPlanModule> modules;
    for (std::vector<Vec2d> &outline : pieces) {
        FloorPlanModule module = prototype;
        module.outline = std::move(outline);
        module.loc = loc;
        modules.push_back(std::move(module));
    }
    for (KkConnection &dock : docks) dock.loc = loc;
    return FloorPlan(std::move(modules), std::move(docks), {});
}

}  // namespace veduta
