#include "facade/lloyd_relaxation.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <iterator>
#include <utility>

#include "core/check.h"
#include "facade/convex_pieces.h"

namespace veduta {

namespace {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPiece = CGAL::Polygon_with_holes_2<ExactKernel>;
using InexactKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = InexactKernel::Point_2;
using Segment = InexactKernel::Segment_2;
using InexactPolygon = CGAL::Polygon_2<InexactKernel>;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<size_t, InexactKernel>;
using Delaunay = CGAL::Delaunay_triangulation_2<InexactKernel, CGAL::Triangulation_data_structure_2<VertexBase>>;

// Points closer than this are one point, and a vertex this close to the line through its
// neighbours lies on it: the Boolean results, rounded to double, leave such vertices, and they
// would make a convex cell look reflex. Far below a stone, far above the rounding of metres.
constexpr double kSamePoint = 1e-9;

double distanceToLine(Vec2d point, Vec2d a, Vec2d b) {
    double span = length(b - a);
    if (span < kSamePoint) return length(point - a);
    return std::abs(cross(b - a, point - a)) / span;
}

// The ring without repeated and collinear vertices; empty when fewer than three remain.
std::vector<Vec2d> cleanedRing(std::vector<Vec2d> ring) {
    bool changed = true;
    while (changed && ring.size() >= 3) {
        changed = false;
        for (size_t i = 0; i < ring.size() && ring.size() >= 3;) {
            Vec2d previous = ring[(i + ring.size() - 1) % ring.size()];
            Vec2d next = ring[(i + 1) % ring.size()];
            if (length(ring[i] - previous) < kSamePoint || distanceToLine(ring[i], previous, next) < kSamePoint) {
                ring.erase(ring.begin() + std::ptrdiff_t(i));
                changed = true;
            } else {
                ++i;
            }
        }
    }
    if (ring.size() < 3) ring.clear();
    return ring;
}

ExactPolygon exactPolygon(const std::vector<Vec2d> &ring) { return cgalPolygon<ExactPolygon>(ring); }

InexactPolygon inexactPolygon(const std::vector<Vec2d> &ring) { return cgalPolygon<InexactPolygon>(ring); }

std::vector<Vec2d> doubleRing(const ExactPolygon &polygon) { return cleanedRing(roundedRing(polygon)); }

RegionPiece doublePiece(const ExactPiece &piece) {
    RegionPiece result{doubleRing(piece.outer_boundary()), {}};
    for (const ExactPolygon &hole : piece.holes()) {
        std::vector<Vec2d> ring = doubleRing(hole);
        if (!ring.empty()) result.holes.push_back(std::move(ring));
    }
    return result;
}

// A wall polygon counter-clockwise, as the Boolean operations want it; a polygon that crosses
// itself is a bug in whoever made the wall.
ExactPolygon wallPolygon(const std::vector<Vec2d> &ring) {
    ExactPolygon polygon = exactPolygon(ring);
    VEDUTA_CHECK(polygon.size() >= 3 && polygon.is_simple(), "a wall face or opening is not a simple polygon");
    if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
    return polygon;
}

// ∫ over the ring's (signed) area of |x|², x measured from `origin`: the polar second moment.
double ringSecondMoment(const std::vector<Vec2d> &ring, Vec2d origin) {
    double sum = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        Vec2d a = ring[i] - origin, b = ring[(i + 1) % ring.size()] - origin;
        sum += cross(a, b) * (dot(a, a) + dot(a, b) + dot(b, b));
    }
    return sum / 12;
}

// The Delaunay neighbours of each seed, which alone bound its Voronoi cell; `present` is false
// for a seed that an equal one shadows. Seeds all on a line have no 2D triangulation: then every
// seed is a neighbour.
void delaunayNeighbours(const std::vector<Vec2d> &seeds, std::vector<std::vector<size_t>> &neighbours,
                        std::vector<bool> &present) {
    std::vector<std::pair<Point, size_t>> points;
    for (size_t i = 0; i < seeds.size(); ++i) points.emplace_back(Point(seeds[i].x, seeds[i].y), i);
    Delaunay triangulation(points.begin(), points.end());
    neighbours.assign(seeds.size(), {});
    present.assign(seeds.size(), false);
    for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v) {
        present[v->info()] = true;
    }
    for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v) {
        std::vector<size_t> &around = neighbours[v->info()];
        if (triangulation.dimension() < 2) {
            for (size_t j = 0; j < seeds.size(); ++j) {
                if (present[j] && j != v->info()) around.push_back(j);
            }
            continue;
        }
        auto circulator = triangulation.incident_vertices(v), end = circulator;
        do {
            if (!triangulation.is_infinite(circulator)) around.push_back(circulator->info());
        } while (++circulator != end);
    }
}

}  // namespace

struct WallRegion::Impl {
    std::vector<ExactPiece> exact;
    std::vector<RegionPiece> pieces;
    std::vector<InexactPolygon> outlines;            // per piece, for the point tests
    std::vector<std::vector<InexactPolygon>> holes;  // per piece
    std::vector<Segment> edges;                      // of every ring
    double area = 0;
    Vec2d lower, upper;

    bool contains(const Point &point) const {
        for (size_t i = 0; i < outlines.size(); ++i) {
            if (outlines[i].bounded_side(point) != CGAL::ON_BOUNDED_SIDE) continue;
            // In a hole of this piece the point may still lie on an island piece within the hole
            // (openings that together ring a part of the wall), so the search goes on.
            bool inHole = std::any_of(holes[i].begin(), holes[i].end(), [&](const InexactPolygon &hole) {
                return hole.bounded_side(point) != CGAL::ON_UNBOUNDED_SIDE;
            });
            if (!inHole) return true;
        }
        return false;
    }

    // Whether a convex polygon lies wholly in the region, decided without Boolean operations (the
    // common case, cells away from the wall's edges): its corners inside, no edge of the region
    // crossing it, and no ring of the region (a small opening) inside it.
    bool holdsWholly(const std::vector<Vec2d> &polygon) const {
        InexactPolygon cell = inexactPolygon(polygon);
        for (const Point &corner : cell.vertices()) {
            if (!contains(corner)) return false;
        }
        for (auto edge = cell.edges_begin(); edge != cell.edges_end(); ++edge) {
            for (const Segment &wallEdge : edges) {
                if (CGAL::do_intersect(*edge, wallEdge)) return false;
            }
        }
        for (const RegionPiece &piece : pieces) {
            for (const auto &hole : piece.holes) {
                if (cell.bounded_side(Point(hole[0].x, hole[0].y)) != CGAL::ON_UNBOUNDED_SIDE) return false;
            }
        }
        return true;
    }
};

WallRegion::WallRegion(const WallFace &wall) : impl_(std::make_unique<Impl>()) {
    CGAL::Polygon_set_2<ExactKernel> set(wallPolygon(wall.outline));
    for (const auto &opening : wall.openings) set.difference(wallPolygon(opening));
    set.polygons_with_holes(std::back_inserter(impl_->exact));

    impl_->lower = {1e300, 1e300};
    impl_->upper = {-1e300, -1e300};
    for (const ExactPiece &exactPiece : impl_->exact) {
        RegionPiece piece = doublePiece(exactPiece);
        if (piece.outline.empty()) continue;
        impl_->area += veduta::area(piece);
        impl_->outlines.push_back(inexactPolygon(piece.outline));
        impl_->holes.emplace_back();
        for (const auto &hole : piece.holes) impl_->holes.back().push_back(inexactPolygon(hole));
        std::vector<const std::vector<Vec2d> *> rings{&piece.outline};
        for (const auto &hole : piece.holes) rings.push_back(&hole);
        for (const auto *ring : rings) {
            for (size_t i = 0; i < ring->size(); ++i) {
                Vec2d a = (*ring)[i], b = (*ring)[(i + 1) % ring->size()];
                impl_->edges.emplace_back(Point(a.x, a.y), Point(b.x, b.y));
                impl_->lower = {std::min(impl_->lower.x, a.x), std::min(impl_->lower.y, a.y)};
                impl_->upper = {std::max(impl_->upper.x, a.x), std::max(impl_->upper.y, a.y)};
            }
        }
        impl_->pieces.push_back(std::move(piece));
    }
}

WallRegion::~WallRegion() = default;
WallRegion::WallRegion(WallRegion &&) noexcept = default;
WallRegion &WallRegion::operator=(WallRegion &&) noexcept = default;

const std::vector<RegionPiece> &WallRegion::pieces() const { return impl_->pieces; }
double WallRegion::area() const { return impl_->area; }
Vec2d WallRegion::lower() const { return impl_->lower; }
Vec2d WallRegion::upper() const { return impl_->upper; }
bool WallRegion::contains(Vec2d point) const { return impl_->contains(Point(point.x, point.y)); }

ClippedCell WallRegion::clip(const std::vector<Vec2d> &convexPolygon) const {
    std::vector<Vec2d> cell = cleanedRing(convexPolygon);
    if (cell.empty()) return {};
    if (impl_->holdsWholly(cell)) return {RegionPiece{cell, {}}};
    ExactPolygon exactCell = exactPolygon(cell);
    ClippedCell result;
    for (const ExactPiece &piece : impl_->exact) {
        if (!CGAL::do_overlap(piece.outer_boundary().bbox(), exactCell.bbox())) continue;
        std::vector<ExactPiece> parts;
        CGAL::intersection(piece, exactCell, std::back_inserter(parts));
        for (const ExactPiece &part : parts) {
            RegionPiece clipped = doublePiece(part);
            if (!clipped.outline.empty()) result.push_back(std::move(clipped));
        }
    }
    return result;
}

WallRegion::Moments WallRegion::moments(const std::vector<Vec2d> &convexPolygon, Vec2d origin) const {
    // Clipping a ring to each edge's half-plane in turn keeps its winding number inside the
    // polygon and makes it 0 outside (Sutherland–Hodgman), so the signed sums over the clipped
    // rings (outlines counter-clockwise, holes clockwise) integrate over exactly the part inside.
    double twiceArea = 0, secondMoment = 0;
    Vec2d weighted;
    for (const RegionPiece &piece : impl_->pieces) {
        std::vector<const std::vector<Vec2d> *> rings{&piece.outline};
        for (const auto &hole : piece.holes) rings.push_back(&hole);
        for (const auto *ring : rings) {
            std::vector<Vec2d> clipped = *ring;
            for (size_t i = 0; i < convexPolygon.size() && !clipped.empty(); ++i) {
                Vec2d a = convexPolygon[i], b = convexPolygon[(i + 1) % convexPolygon.size()];
                Vec2d outward{b.y - a.y, a.x - b.x};
                clipped = clipToHalfPlane(clipped, outward, dot(a, outward));
            }
            for (size_t i = 0; i < clipped.size(); ++i) {
                Vec2d a = clipped[i], b = clipped[(i + 1) % clipped.size()];
                twiceArea += cross(a, b);
                weighted = weighted + (a + b) * cross(a, b);
            }
            secondMoment += ringSecondMoment(clipped, origin);
        }
    }
    Moments result{twiceArea / 2, {}, secondMoment};
    if (twiceArea > 0) result.centroid = weighted * (1 / (3 * twiceArea));
    return result;
}

std::vector<Vec2d> clipToHalfPlane(const std::vector<Vec2d> &polygon, Vec2d normal, double offset) {
    std::vector<Vec2d> kept;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        double da = dot(a, normal) - offset, db = dot(b, normal) - offset;
        if (da <= 0) kept.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) kept.push_back(a + (b - a) * (da / (da - db)));
    }
    return cleanedRing(std::move(kept));
}

double area(const RegionPiece &piece) {
    double sum = signedArea(piece.outline);
    for (const auto &hole : piece.holes) sum += signedArea(hole);
    return sum;
}

double area(const ClippedCell &cell) {
    double sum = 0;
    for (const RegionPiece &piece : cell) sum += area(piece);
    return sum;
}

namespace {

// The Voronoi cell of every seed, cut from a box around the region and the seeds, not yet clipped
// to the region; empty for a seed that an equal one shadows.
std::vector<std::vector<Vec2d>> voronoiCells(const WallRegion &region, const std::vector<Vec2d> &seeds) {
    std::vector<std::vector<size_t>> neighbours;
    std::vector<bool> present;
    delaunayNeighbours(seeds, neighbours, present);

    // A box that holds the region and every seed, wide enough that no cell is cut by it inside
    // the region.
    Vec2d lower = region.lower(), upper = region.upper();
    for (Vec2d s : seeds) {
        lower = {std::min(lower.x, s.x), std::min(lower.y, s.y)};
        upper = {std::max(upper.x, s.x), std::max(upper.y, s.y)};
    }
    double margin = length(upper - lower) + 1;
    lower = lower - Vec2d{margin, margin};
    upper = upper + Vec2d{margin, margin};
    const std::vector<Vec2d> box{lower, {upper.x, lower.y}, upper, {lower.x, upper.y}};

    std::vector<std::vector<Vec2d>> cells(seeds.size());
    for (size_t i = 0; i < seeds.size(); ++i) {
        if (!present[i]) continue;
        cells[i] = box;
        for (size_t j : neighbours[i]) {
            // The points nearer seed i than seed j: dot(x − midpoint, j − i) <= 0.
            Vec2d towards = seeds[j] - seeds[i];
            cells[i] = clipToHalfPlane(cells[i], towards, dot((seeds[i] + seeds[j]) * 0.5, towards));
        }
    }
    return cells;
}

}  // namespace

std::vector<ClippedCell> clippedVoronoiCells(const WallRegion &region, const std::vector<Vec2d> &seeds) {
    std::vector<ClippedCell> clipped;
    for (const std::vector<Vec2d> &cell : voronoiCells(region, seeds)) {
        clipped.push_back(cell.empty() ? ClippedCell{} : region.clip(cell));
    }
    return clipped;
}

LloydResult relaxLloyd(const WallRegion &region, std::vector<Vec2d> seeds, size_t fixedCount,
                       const LloydSettings &settings) {
    VEDUTA_CHECK(fixedCount <= seeds.size(), "more fixed seeds than seeds");
    LloydResult result;
    // The moments of each seed's clipped cell, and their energy, for the current seeds.
    std::vector<WallRegion::Moments> moments(seeds.size());
    auto measure = [&] {
        std::vector<std::vector<Vec2d>> cells = voronoiCells(region, seeds);
        double energy = 0;
        for (size_t i = 0; i < seeds.size(); ++i) {
            moments[i] = cells[i].empty() ? WallRegion::Moments{} : region.moments(cells[i], seeds[i]);
            energy += moments[i].secondMoment;
        }
        result.energies.push_back(energy);
    };
    measure();
    size_t freeCount = seeds.size() - fixedCount;
    for (int step = 0; step < settings.maxIterations && freeCount > 0; ++step) {
        double total = 0, largest = 0;
        for (size_t i = fixedCount; i < seeds.size(); ++i) {
            if (moments[i].area <= 0) continue;
            double shift = length(moments[i].centroid - seeds[i]);
            seeds[i] = moments[i].centroid;
            total += shift;
            largest = std::max(largest, shift);
        }
        result.meanShifts.push_back(total / double(freeCount));
        measure();
        if (largest < settings.shiftThreshold) break;
    }
    result.cells = clippedVoronoiCells(region, seeds);
    result.seeds = std::move(seeds);
    return result;
}

}  // namespace veduta
