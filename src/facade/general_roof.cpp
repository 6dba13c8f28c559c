#include "facade/general_roof.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "core/check.h"

namespace veduta {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using HullMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Vec3d lift(Vec2d p, double z) { return {p.x, p.y, z}; }
Vec2d plan(const Vec3d &p) { return {p.x, p.y}; }
Vec3d minus(const Vec3d &a, const Vec3d &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot3(const Vec3d &a, const Vec3d &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross3(const Vec3d &a, const Vec3d &b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3d unit(const Vec3d &v) {
    double l = std::sqrt(dot3(v, v));
    return {v.x / l, v.y / l, v.z / l};
}

void checkOutline(const std::vector<Vec2d> &outline, const std::vector<bool> &connected) {
    if (outline.size() < 3) throw std::invalid_argument(fmt::format("a module outline of {} points", outline.size()));
    if (connected.size() != outline.size()) {
        throw std::invalid_argument(
            fmt::format("{} connection flags for an outline of {} edges", connected.size(), outline.size()));
    }
    // A simple outline that turns left at every corner is strictly convex and counter-clockwise.
    std::vector<Kernel::Point_2> points;
    for (Vec2d p : outline) points.push_back({p.x, p.y});
    if (!CGAL::is_simple_2(points.begin(), points.end(), Kernel()))
        throw std::invalid_argument("a module outline that is not convex and counter-clockwise (Def 4.1)");
    for (size_t i = 0; i < points.size(); ++i) {
        const auto &a = points[i], &b = points[(i + 1) % points.size()], &c = points[(i + 2) % points.size()];
        switch (CGAL::orientation(a, b, c)) {
        case CGAL::LEFT_TURN: break;
        case CGAL::COLLINEAR:
            throw std::invalid_argument(
                fmt::format("the module outline turns straight at point {}", (i + 1) % points.size()));
        default: throw std::invalid_argument("a module outline that is not convex and counter-clockwise (Def 4.1)");
        }
    }
}

void checkParameters(size_t edges, const GeneralRoofParameters &p) {
    if (p.edgeI >= edges || p.edgeJ >= edges) {
        throw std::invalid_argument(
            fmt::format("a ridge on edges {} and {} of an outline of {}", p.edgeI, p.edgeJ, edges));
    }
    for (double f : {p.c, p.d, p.a, p.b}) {
        if (!(f >= 0 && f <= 1)) throw std::invalid_argument(fmt::format("a roof fraction of {} is not in [0, 1]", f));
    }
    if (p.a > p.b) throw std::invalid_argument(fmt::format("a ridge from {} back to {}", p.a, p.b));
    if (!(p.height > 0 && std::isfinite(p.height))) {
        throw std::invalid_argument(fmt::format("a roof height of {} m is not a height", p.height));
    }
}

Vec2d pointOnEdge(const std::vector<Vec2d> &outline, size_t edge, double t) {
    Vec2d from = outline[edge], to = outline[(edge + 1) % outline.size()];
    return from * (1 - t) + to * t;
}

// Def 4.13, L944, with the q_ei that the OCR lost.
RoofRidge ridgeOf(const std::vector<Vec2d> &outline, double eavesZ, const GeneralRoofParameters &p) {
    Vec2d qi = pointOnEdge(outline, p.edgeI, p.c), qj = pointOnEdge(outline, p.edgeJ, p.d);
    double z = eavesZ + p.height;
    return {lift(qi + (qj - qi) * p.a, z), lift(qi + (qj - qi) * p.b, z)};
}

Vec3d toVec3d(const Kernel::Point_3 &p) { return {p.x(), p.y(), p.z()}; }

// Groups of hull triangles that lie in one plane: the hull triangulates a quad whose corners
// are coplanar only up to rounding.
std::vector<size_t> coplanarGroups(const HullMesh &hull, double tolerance) {
    std::vector<size_t> group(hull.number_of_faces());
    std::iota(group.begin(), group.end(), size_t{0});
    auto root = [&](size_t f) {
        while (group[f] != f) f = group[f] = group[group[f]];
        return f;
    };
    for (HullMesh::Halfedge_index h : hull.halfedges()) {
        HullMesh::Halfedge_index o = hull.opposite(h);
        if (hull.is_border(h) || hull.is_border(o)) continue;
        HullMesh::Face_index f = hull.face(h);
        Kernel::Plane_3 plane(hull.point(hull.source(h)), hull.point(hull.target(h)),
                              hull.point(hull.target(hull.next(h))));
        Kernel::Point_3 across = hull.point(hull.target(hull.next(o)));
        Kernel::Vector_3 v = plane.orthogonal_vector();
        Vec3d n = unit({v.x(), v.y(), v.z()});
        double distance = dot3(n, minus(toVec3d(across), toVec3d(hull.point(hull.source(h)))));
        if (std::abs(distance) <= tolerance) group[root(f)] = root(hull.face(o));
    }
    for (size_t f = 0; f < group.size(); ++f) group[f] = root(f);
    return group;
}

// Each group's outline, walked as the hull's faces are: counter-clockwise seen from outside.
std::vector<std::vector<Vec3d>> mergedFaces(const HullMesh &hull, double tolerance) {
    std::vector<size_t> group = coplanarGroups(hull, tolerance);
    std::map<size_t, std::map<HullMesh::Vertex_index, HullMesh::Halfedge_index>> boundaries;
    for (HullMesh::Halfedge_index h : hull.halfedges()) {
        if (hull.is_border(h)) continue;
        HullMesh::Halfedge_index o = hull.opposite(h);
        size_t g = group[hull.face(h)];
        if (!hull.is_border(o) && group[hull.face(o)] == g) continue;
        boundaries[g][hull.source(h)] = h;
    }
    std::vector<std::vector<Vec3d>> faces;
    for (const auto &[g, next] : boundaries) {
        std::vector<Vec3d> corners;
        HullMesh::Vertex_index start = next.begin()->first, v = start;
        do {
            corners.push_back(toVec3d(hull.point(v)));
            v = hull.target(next.at(v));
        } while (v != start && corners.size() <= next.size());
        VEDUTA_CHECK(v == start && corners.size() == next.size(), "coplanar hull faces without one outline");
        faces.push_back(std::move(corners));
    }
    return faces;
}

// The outline edge that runs along the face's bottom in the outline's direction, if any.
size_t outlineEdgeOf(const std::vector<Vec3d> &corners, const std::vector<Vec2d> &outline, double eavesZ) {
    for (size_t k = 0; k < corners.size(); ++k) {
        const Vec3d &u = corners[k], &v = corners[(k + 1) % corners.size()];
        if (u.z != eavesZ || v.z != eavesZ) continue;
        for (size_t i = 0; i < outline.size(); ++i) {
            if (plan(u) == outline[i] && plan(v) == outline[(i + 1) % outline.size()]) return i;
        }
    }
    return kNoOutlineEdge;
}

bool isBottom(const std::vector<Vec3d> &corners, double eavesZ) {
    return std::all_of(corners.begin(), corners.end(), [&](const Vec3d &c) { return c.z == eavesZ; });
}

// Where the line through a0 along dir0 meets the line through a1 along dir1.
Vec2d meet(Vec2d a0, Vec2d dir0, Vec2d a1, Vec2d dir1) {
    double t = cross(a1 - a0, dir1) / cross(dir0, dir1);
    return a0 + dir0 * t;
}

Vec2d leftNormal(Vec2d d) { return Vec2d{-d.y, d.x} * (1 / length(d)); }

// The deck's corners: each edge's line moved inwards by the parapet's width where it has one.
// Empty when the width is so wide that an edge of the deck vanishes or turns round.
std::vector<Vec2d> deckOutline(const std::vector<Vec2d> &outline, const std::vector<bool> &connected, double width) {
    size_t n = outline.size();
    auto shifted = [&](size_t i) {
        return outline[i] + leftNormal(outline[(i + 1) % n] - outline[i]) * (connected[i] ? 0 : width);
    };
    auto direction = [&](size_t i) { return outline[(i + 1) % n] - outline[i]; };
    std::vector<Vec2d> deck;
    for (size_t i = 0; i < n; ++i) {
        size_t before = (i + n - 1) % n;
        deck.push_back(meet(shifted(before), direction(before), shifted(i), direction(i)));
    }
    for (size_t i = 0; i < n; ++i)
        if (dot(deck[(i + 1) % n] - deck[i], direction(i)) <= 0) return {};
    return deck;
}

// The deck of the parapet's width, or of a narrower parapet where a module is too thin for it (a
// sliver that a footprint's partition cut): 0.9 of the width at which the first edge of the deck
// vanishes, found by bisection, since the deck only shrinks as the width grows.
std::vector<Vec2d> deckThatFits(const std::vector<Vec2d> &outline, const std::vector<bool> &connected, double width) {
    std::vector<Vec2d> deck = deckOutline(outline, connected, width);
    if (!deck.empty()) return deck;
    double fits = 0, vanishes = width;
    for (int step = 0; step < 40; ++step) {
        double mid = 0.5 * (fits + vanishes);
        (deckOutline(outline, connected, mid).empty() ? vanishes : fits) = mid;
    }
    return deckOutline(outline, connected, 0.9 * fits);
}

void addParapet(ModuleRoof &roof, const std::vector<Vec2d> &deck, size_t i, double height) {
    size_t n = roof.outline.size();
    Vec2d p = roof.outline[i], q = roof.outline[(i + 1) % n], in0 = deck[i], in1 = deck[(i + 1) % n];
    double z0 = roof.eavesZ, z1 = roof.eavesZ + height;
    auto add = [&](std::vector<Vec3d> corners) {
        roof.faces.push_back({std::move(corners), RoofFaceKind::Parapet, i});
    };
    add({lift(p, z0), lift(q, z0), lift(q, z1), lift(p, z1)});
    add({lift(p, z1), lift(q, z1), lift(in1, z1), lift(in0, z1)});
    add({lift(in1, z0), lift(in0, z0), lift(in0, z1), lift(in1, z1)});
    // Where the neighbouring edge is a seam the parapet ends flush with it, and the end shows
    // wherever the neighbour is lower.
    if (roof.connected[(i + n - 1) % n]) add({lift(in0, z0), lift(p, z0), lift(p, z1), lift(in0, z1)});
    if (roof.connected[(i + 1) % n]) add({lift(q, z0), lift(in1, z0), lift(in1, z1), lift(q, z1)});
}

bool coversPoint(const std::vector<Vec3d> &corners, Vec2d p, double tolerance) {
    bool inside = false;
    for (size_t k = 0, n = corners.size(); k < n; ++k) {
        Vec2d a = plan(corners[k]), b = plan(corners[(k + 1) % n]), ab = b - a;
        double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
        if (length(p - (a + ab * t)) <= tolerance) return true;
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) inside = !inside;
    }
    return inside;
}

// Triangles over the face's corners; CGAL's triangulation also takes the non-convex faces a
// merge makes (its valleys bend inwards).
std::vector<std::array<uint32_t, 3>> triangulate(const std::vector<Vec3d> &corners) {
    HullMesh polygon;
    std::vector<HullMesh::Vertex_index> vertices;
    for (const Vec3d &c : corners) vertices.push_back(polygon.add_vertex({c.x, c.y, c.z}));
    polygon.add_face(vertices);
    CGAL::Polygon_mesh_processing::triangulate_faces(polygon);
    std::vector<std::array<uint32_t, 3>> triangles;
    for (HullMesh::Face_index f : polygon.faces()) {
        std::array<uint32_t, 3> triangle{};
        size_t k = 0;
        for (HullMesh::Vertex_index v : polygon.vertices_around_face(polygon.halfedge(f))) triangle[k++] = v;
        triangles.push_back(triangle);
    }
    return triangles;
}

Vec2f uvOf(const Vec3d &p, const Vec3d &normal, double eavesZ) {
    if (std::abs(normal.z) > 1 - 1e-12) return {static_cast<float>(p.x), static_cast<float>(p.y)};
    Vec3d u = unit({-normal.y, normal.x, 0}), v = cross3(normal, u);
    return {static_cast<float>(p.x * u.x + p.y * u.y), static_cast<float>((p.z - eavesZ) / v.z)};
}

MaterialId materialOf(RoofFaceKind kind, const RoofMaterials &materials) {
    switch (kind) {
    case RoofFaceKind::Slope: return materials.slope;
    case RoofFaceKind::Interface: return materials.interface;
    case RoofFaceKind::Parapet: return materials.parapet;
    }
    return kNoMaterial;
}

}  // namespace

ModuleRoof generalRoof(const std::vector<Vec2d> &outline, double eavesZ, const std::vector<bool> &connected,
                       const GeneralRoofParameters &parameters) {
    checkOutline(outline, connected);
    checkParameters(outline.size(), parameters);
    ModuleRoof roof{outline, connected, eavesZ, ridgeOf(outline, eavesZ, parameters), {}};
    std::vector<Kernel::Point_3> points;
    for (Vec2d p : outline) points.push_back({p.x, p.y, eavesZ});
    for (const Vec3d &r : {roof.ridge->a, roof.ridge->b}) points.push_back({r.x, r.y, r.z});
    HullMesh hull;
    CGAL::convex_hull_3(points.begin(), points.end(), hull);
    for (std::vector<Vec3d> &corners : mergedFaces(hull, roofTolerance(roof))) {
        if (isBottom(corners, eavesZ)) continue;
        ModuleRoofFace face{std::move(corners), RoofFaceKind::Slope, kNoOutlineEdge};
        face.edge = outlineEdgeOf(face.corners, outline, eavesZ);
        if (std::abs(faceNormal(face).z) <= 1e-9) face.kind = RoofFaceKind::Interface;
        roof.faces.push_back(std::move(face));
    }
    return roof;
}

ModuleRoof flatRoof(const std::vector<Vec2d> &outline, double eavesZ, const std::vector<bool> &connected,
                    const ParapetParameters &parapet) {
    checkOutline(outline, connected);
    if (!(parapet.height > 0 && parapet.width > 0 && std::isfinite(parapet.height) && std::isfinite(parapet.width))) {
        throw std::invalid_argument(fmt::format("a parapet {} m high and {} m wide", parapet.height, parapet.width));
    }
    ModuleRoof roof{outline, connected, eavesZ, std::nullopt, {}};
    std::vector<Vec2d> deck = deckThatFits(outline, connected, parapet.width);
    if (deck.empty())  // only where rounding defeats every width: a strictly convex outline has a deck
        throw std::invalid_argument(fmt::format("a parapet of any width leaves no deck"));
    std::vector<Vec3d> deckCorners;
    for (Vec2d p : deck) deckCorners.push_back(lift(p, eavesZ));
    roof.faces.push_back({std::move(deckCorners), RoofFaceKind::Slope, kNoOutlineEdge});
    for (size_t i = 0; i < outline.size(); ++i) {
        if (!connected[i]) addParapet(roof, deck, i, parapet.height);
    }
    return roof;
}

double roofTolerance(const ModuleRoof &roof) {
    double extent = 1;
    for (Vec2d p : roof.outline) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    return 1e-9 * extent;
}

Vec3d faceNormal(const ModuleRoofFace &face) {
    Vec3d sum;
    for (size_t k = 0, n = face.corners.size(); k < n; ++k) {
        const Vec3d &a = face.corners[k], &b = face.corners[(k + 1) % n];
        sum.x += (a.y - b.y) * (a.z + b.z);
        sum.y += (a.z - b.z) * (a.x + b.x);
        sum.z += (a.x - b.x) * (a.y + b.y);
    }
    return unit(sum);
}

RoofPlane facePlane(const ModuleRoofFace &face) {
    Vec3d n = faceNormal(face), centre;
    for (const Vec3d &c : face.corners) centre = {centre.x + c.x, centre.y + c.y, centre.z + c.z};
    double count = static_cast<double>(face.corners.size());
    centre = {centre.x / count, centre.y / count, centre.z / count};
    return {centre.z + (n.x * centre.x + n.y * centre.y) / n.z, -n.x / n.z, -n.y / n.z};
}

std::vector<RoofPlane> slopePlanes(const ModuleRoof &roof) {
    std::vector<RoofPlane> planes;
    for (const ModuleRoofFace &face : roof.faces) {
        if (face.kind == RoofFaceKind::Slope) planes.push_back(facePlane(face));
    }
    return planes;
}

std::optional<double> roofHeightAt(const ModuleRoof &roof, Vec2d p) {
    double tolerance = roofTolerance(roof);
    bool covered = std::any_of(roof.faces.begin(), roof.faces.end(), [&](const ModuleRoofFace &face) {
        return face.kind != RoofFaceKind::Interface && std::abs(faceNormal(face).z) > 1e-9 &&
            coversPoint(face.corners, p, tolerance);
    });
    if (!covered) return std::nullopt;
    double height = std::numeric_limits<double>::infinity();
    for (const RoofPlane &plane : slopePlanes(roof)) height = std::min(height, plane.heightAt(p));
    return height;
}

Mesh roofMesh(const ModuleRoof &roof, const RoofMaterials &materials) {
    Mesh mesh;
    for (const ModuleRoofFace &face : roof.faces) {
        Vec3d n = faceNormal(face);
        auto first = static_cast<uint32_t>(mesh.positions.size());
        for (const Vec3d &c : face.corners) {
            mesh.positions.push_back({static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
            mesh.normals.push_back({static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)});
            mesh.uvs.push_back(uvOf(c, n, roof.eavesZ));
        }
        for (const auto &triangle : triangulate(face.corners)) {
            for (uint32_t k : triangle) mesh.indices.push_back(first + k);
            mesh.triangleMaterials.push_back(materialOf(face.kind, materials));
        }
    }
    return mesh;
}

}  // namespace veduta
