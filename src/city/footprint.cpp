#include "city/footprint.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include <fmt/format.h>

#include "city/triangulation_inside.h"

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Segment = Kernel::Segment_2;

// A constrained Delaunay triangulation whose vertices know their polygon index and whose faces
// know whether they lie inside the polygon.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Kernel>,
        CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<bool, Kernel>>>>;

std::vector<Point> toCgal(std::span<const Vec2f> polygon) {
    std::vector<Point> points;
    points.reserve(polygon.size());
    for (Vec2f p : polygon) points.emplace_back(p.x, p.y);
    return points;
}

void checkPoints(const Footprint &footprint, const FileLoc &loc) {
    const std::vector<Vec2f> &points = footprint.points;
    if (points.size() < 3)
        throw InputError(loc, fmt::format("a footprint needs at least 3 points, not {}", points.size()));
    if (points.size() > kMaxOutlinePoints)
        throw InputError(
            loc,
            fmt::format("an outline of {} points is more than veduta takes ({})", points.size(), kMaxOutlinePoints));
    for (size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
            throw InputError(loc, fmt::format("footprint point {} is not a finite number", i + 1));
        }
    }
    // Repeated points, found by sorting rather than by comparing every pair; the message names
    // the later point and the first one it repeats, as a reader counts them.
    std::vector<uint32_t> order(points.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [&](uint32_t i) { return std::tuple(points[i].x, points[i].y, i); };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    std::optional<std::pair<uint32_t, uint32_t>> repeat;  // (later, first)
    size_t group = 0;                                     // where the run of equal points began
    for (size_t k = 1; k < order.size(); ++k) {
        uint32_t a = order[k - 1], b = order[k];
        if (points[a].x != points[b].x || points[a].y != points[b].y) {
            group = k;
            continue;
        }
        if (!repeat || b < repeat->first) repeat = std::pair(b, order[group]);
    }
    if (repeat) {
        Vec2f p = points[repeat->first];
        throw InputError(loc,
                         fmt::format("footprint point {} repeats point {} ({} {})", repeat->first + 1,
                                     repeat->second + 1, p.x, p.y));
    }
}

// Reverses the ring and keeps each street flag on its edge: old edge i (p_i → p_i+1) becomes
// new edge n − 2 − i (mod n), running p_i+1 → p_i.
void reverseFootprint(Footprint &footprint) {
    std::reverse(footprint.points.begin(), footprint.points.end());
    std::reverse(footprint.streetEdges.begin(), footprint.streetEdges.end());
    std::rotate(footprint.streetEdges.begin(), footprint.streetEdges.begin() + 1, footprint.streetEdges.end());
}

}  // namespace

float Footprint::edgeLength(size_t edge) const { return length(lift(edgeEnd(edge), 0) - lift(edgeStart(edge), 0)); }

float Footprint::perimeterBefore(size_t edge) const {
    float distance = 0;
    for (size_t e = 0; e < edge; ++e) distance += edgeLength(e);
    return distance;
}

Vec3f Footprint::edgeDirection(size_t edge) const {
    return normalize(lift(edgeEnd(edge), 0) - lift(edgeStart(edge), 0));
}

Vec3f Footprint::outwardNormal(size_t edge) const { return cross(edgeDirection(edge), Vec3f{0, 0, 1}); }

bool isSimplePolygon(std::span<const Vec2f> polygon) {
    std::vector<Point> points = toCgal(polygon);
    return CGAL::is_simple_2(points.begin(), points.end(), Kernel());
}

bool isCounterClockwise(std::span<const Vec2f> polygon) {
    std::vector<Point> points = toCgal(polygon);
    return CGAL::orientation_2(points.begin(), points.end(), Kernel()) == CGAL::COUNTERCLOCKWISE;
}

float signedArea(std::span<const Vec2f> polygon) {
    double twice = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec2f a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        twice += double(a.x) * b.y - double(b.x) * a.y;
    }
    return float(twice / 2);
}

bool liesInside(std::span<const Vec2f> inner, std::span<const Vec2f> outer) {
    std::vector<Point> in = toCgal(inner), out = toCgal(outer);
    for (const Point &p : in) {
        if (CGAL::bounded_side_2(out.begin(), out.end(), p, Kernel()) != CGAL::ON_BOUNDED_SIDE) return false;
    }
    for (size_t i = 0; i < in.size(); ++i) {
        Segment a(in[i], in[(i + 1) % in.size()]);
        for (size_t j = 0; j < out.size(); ++j) {
            if (CGAL::do_intersect(a, Segment(out[j], out[(j + 1) % out.size()]))) return false;
        }
    }
    return true;
}

std::vector<Vec2f> offsetPolygon(std::span<const Vec2f> ring, float distance) {
    return offsetPolygon(ring, std::vector<float>(ring.size(), distance));
}

std::vector<Vec2f> offsetPolygon(std::span<const Vec2f> ring, std::span<const float> distances) {
    std::vector<Vec2f> moved;
    size_t n = ring.size();
    auto rightNormal = [&](size_t edge) {
        Vec3f along = normalize(lift(ring[(edge + 1) % n], 0) - lift(ring[edge], 0));
        return cross(along, Vec3f{0, 0, 1});
    };
    for (size_t i = 0; i < n; ++i) {
        Vec3f a = rightNormal((i + n - 1) % n), b = rightNormal(i);
        float da = distances[(i + n - 1) % n], db = distances[i];
        Vec3f shift;
        if (da == db) {
            // The mitre, which also holds where the two edges run straight on.
            shift = (a + b) * (da / (1 + dot(a, b)));
        } else {
            // shift · a = da and shift · b = db.
            float det = a.x * b.y - a.y * b.x;
            shift = {(da * b.y - db * a.y) / det, (a.x * db - b.x * da) / det, 0};
        }
        Vec3f corner = lift(ring[i], 0) + shift;
        moved.push_back({corner.x, corner.y});
    }
    return moved;
}

bool areDisjoint(std::span<const Vec2f> a, std::span<const Vec2f> b) {
    std::vector<Point> pa = toCgal(a), pb = toCgal(b);
    for (size_t i = 0; i < pa.size(); ++i) {
        Segment edge(pa[i], pa[(i + 1) % pa.size()]);
        for (size_t j = 0; j < pb.size(); ++j) {
            if (CGAL::do_intersect(edge, Segment(pb[j], pb[(j + 1) % pb.size()]))) return false;
        }
    }
    // With no crossings, one lies inside the other exactly when its first point does.
    return CGAL::bounded_side_2(pb.begin(), pb.end(), pa[0], Kernel()) == CGAL::ON_UNBOUNDED_SIDE &&
        CGAL::bounded_side_2(pa.begin(), pa.end(), pb[0], Kernel()) == CGAL::ON_UNBOUNDED_SIDE;
}

double distanceToSegment(Vec2f p, Vec2f a, Vec2f b) {
    double abx = double(b.x) - a.x, aby = double(b.y) - a.y, apx = double(p.x) - a.x, apy = double(p.y) - a.y;
    double length2 = abx * abx + aby * aby;
    double t = length2 > 0 ? std::clamp((apx * abx + apy * aby) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(apx - t * abx, apy - t * aby);
}

bool covers(std::span<const Vec2f> polygon, Vec2f p, double tolerance) {
    std::vector<Point> points = toCgal(polygon);
    if (CGAL::bounded_side_2(points.begin(), points.end(), Point(p.x, p.y), Kernel()) != CGAL::ON_UNBOUNDED_SIDE)
        return true;
    for (size_t i = 0; i < polygon.size(); ++i)
        if (distanceToSegment(p, polygon[i], polygon[(i + 1) % polygon.size()]) <= tolerance) return true;
    return false;
}

namespace {

bool crossClearly(Vec2f a, Vec2f b, Vec2f c, Vec2f d, double tolerance) {
    if (!CGAL::do_intersect(Segment(Point(a.x, a.y), Point(b.x, b.y)), Segment(Point(c.x, c.y), Point(d.x, d.y))))
        return false;
    return distanceToSegment(a, c, d) > tolerance && distanceToSegment(b, c, d) > tolerance &&
        distanceToSegment(c, a, b) > tolerance && distanceToSegment(d, a, b) > tolerance;
}

}  // namespace

std::optional<size_t> edgeLeaving(std::span<const Vec2f> inner, std::span<const Vec2f> outer, double tolerance) {
    for (size_t i = 0; i < inner.size(); ++i) {
        Vec2f a = inner[i], b = inner[(i + 1) % inner.size()];
        if (!covers(outer, {(a.x + b.x) / 2, (a.y + b.y) / 2}, tolerance)) return i;
        for (size_t j = 0; j < outer.size(); ++j)
            if (crossClearly(a, b, outer[j], outer[(j + 1) % outer.size()], tolerance)) return i;
    }
    return std::nullopt;
}

Vec2f areaCentroid(std::span<const Vec2f> polygon) {
    // Relative to the first corner, so that polygons far from the origin keep their precision.
    Vec2f origin = polygon[0];
    double area = 0, x = 0, y = 0;
    for (size_t i = 1; i + 1 < polygon.size(); ++i) {
        double ax = polygon[i].x - origin.x, ay = polygon[i].y - origin.y;
        double bx = polygon[i + 1].x - origin.x, by = polygon[i + 1].y - origin.y;
        double twiceArea = ax * by - ay * bx;
        area += twiceArea;
        x += twiceArea * (ax + bx) / 3;
        y += twiceArea * (ay + by) / 3;
    }
    return {float(origin.x + x / area), float(origin.y + y / area)};
}

std::vector<uint32_t> triangulatePolygon(std::span<const Vec2f> polygon) {
    std::vector<Vec2f> ring(polygon.begin(), polygon.end());
    return triangulatePolygonWithHoles(std::span(&ring, 1));
}

std::vector<uint32_t> triangulatePolygonWithHoles(std::span<const std::vector<Vec2f>> rings) {
    Cdt cdt;
    uint32_t index = 0;
    for (const std::vector<Vec2f> &ring : rings) {
        std::vector<Cdt::Vertex_handle> vertices;
        for (Vec2f p : ring) {
            vertices.push_back(cdt.insert(Point(p.x, p.y)));
            vertices.back()->info() = index++;
        }
        for (size_t i = 0; i < vertices.size(); ++i)
            cdt.insert_constraint(vertices[i], vertices[(i + 1) % vertices.size()]);
    }
    markInside(cdt);
    std::vector<uint32_t> indices;
    for (Cdt::Face_handle f : cdt.finite_face_handles()) {
        if (!f->info()) continue;
        for (int k = 0; k < 3; ++k) indices.push_back(f->vertex(k)->info());
    }
    return indices;
}

std::optional<std::string> normaliseFootprint(Footprint &footprint, const FileLoc &loc) {
    checkPoints(footprint, loc);
    if (footprint.streetEdges.empty()) footprint.streetEdges.assign(footprint.points.size(), false);
    if (footprint.streetEdges.size() != footprint.points.size()) {
        throw InputError(loc,
                         fmt::format("a footprint of {} edges has {} street flags", footprint.points.size(),
                                     footprint.streetEdges.size()));
    }
    if (!isSimplePolygon(footprint.points)) {
        throw InputError(loc, "the footprint's outline crosses or touches itself (or has no area)");
    }
    if (isCounterClockwise(footprint.points)) return std::nullopt;
    reverseFootprint(footprint);
    return fmt::format("{}: the footprint runs clockwise; it was reversed to run counter-clockwise", loc.toString());
}

}  // namespace veduta
