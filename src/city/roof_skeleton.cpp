#include "city/roof_skeleton.h"

#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/create_straight_skeleton_from_polygon_with_holes_2.h>

#include <algorithm>
#include <map>
#include <unordered_map>

#include <fmt/format.h>

#include "city/roof_faces.h"

namespace veduta {

namespace {

using Ring = std::vector<Vec2f>;

std::vector<RoofEdge> edgesOf(const RoofFootprint &footprint) {
    std::vector<RoofEdge> edges;
    std::vector<Ring> rings{footprint.outer};
    rings.insert(rings.end(), footprint.holes.begin(), footprint.holes.end());
    for (const Ring &ring : rings) {
        size_t first = edges.size(), n = ring.size();
        float before = 0;
        for (size_t i = 0; i < n; ++i) {
            Vec2f a = ring[i], b = ring[(i + 1) % n];
            edges.push_back({a, b, first + (i + n - 1) % n, first + (i + 1) % n, before});
            before += length(lift(b, 0) - lift(a, 0));
        }
    }
    return edges;
}

CGAL::Polygon_2<RoofKernel> toCgalPolygon(const Ring &ring) {
    CGAL::Polygon_2<RoofKernel> polygon;
    for (Vec2f p : ring) polygon.push_back(RoofKernel::Point_2(p.x, p.y));
    return polygon;
}

Vec3f toVec3f(const RoofKernel::Point_3 &p) { return {float(p.x()), float(p.y()), float(p.z())}; }

}  // namespace

RoofKernel::Plane_3 slopePlane(const SkeletonRoof &roof, size_t edge, double raise) {
    Vec2f a = roof.edges[edge].start, b = roof.edges[edge].end;
    double dx = double(b.x) - a.x, dy = double(b.y) - a.y, span = std::hypot(dx, dy);
    // Away from the building, to the edge's right, and up by the slope's run.
    RoofKernel::Vector_3 normal(dy / span * roof.slope, -dx / span * roof.slope, 1);
    return {RoofKernel::Point_3(a.x, a.y, roof.eavesZ + raise), normal};
}

std::optional<SkeletonRoof> skeletonRoof(const RoofFootprint &footprint, float eavesZ, float slope) {
    CGAL::Polygon_with_holes_2<RoofKernel> polygon(toCgalPolygon(footprint.outer));
    for (const Ring &hole : footprint.holes) polygon.add_hole(toCgalPolygon(hole));
    auto skeleton = CGAL::create_interior_straight_skeleton_2(polygon, RoofKernel());
    if (!skeleton) return std::nullopt;

    SkeletonRoof roof{edgesOf(footprint), {}, {}, 0, footprint.base, eavesZ, slope};
    std::unordered_map<int, uint32_t> cornerOf;
    for (auto v = skeleton->vertices_begin(); v != skeleton->vertices_end(); ++v) {
        cornerOf[v->id()] = uint32_t(roof.corners.size());
        roof.corners.emplace_back(v->point().x(), v->point().y(), eavesZ + v->time() * slope);
    }
    roof.skeletonCorners = roof.corners.size();
    std::map<std::pair<float, float>, size_t> edgeStartingAt;
    for (size_t e = 0; e < roof.edges.size(); ++e) edgeStartingAt[{roof.edges[e].start.x, roof.edges[e].start.y}] = e;

    roof.faces.resize(roof.edges.size());
    for (auto face = skeleton->faces_begin(); face != skeleton->faces_end(); ++face) {
        // Every face belongs to one footprint edge: its halfedge() runs along it, to the edge's
        // end; the loop from there closes with the edge's start, which goes first.
        std::vector<uint32_t> corners;
        auto edge = face->halfedge(), h = edge;
        do {
            corners.push_back(cornerOf.at(h->vertex()->id()));
            h = h->next();
        } while (h != edge);
        std::rotate(corners.begin(), corners.end() - 1, corners.end());
        const auto &start = edge->opposite()->vertex()->point();
        size_t e = edgeStartingAt.at({float(start.x()), float(start.y())});
        roof.faces[e] = {std::move(corners), slopePlane(roof, e, 0), e, RoofCovering};
    }
    return roof;
}

bool isSimpleFromAbove(const SkeletonRoof &roof, const RoofFace &face) {
    std::vector<Vec2f> outline;
    for (uint32_t c : face.corners) outline.push_back({float(roof.corners[c].x()), float(roof.corners[c].y())});
    return isSimplePolygon(outline);
}

std::variant<Mesh, std::string> roofMesh(const SkeletonRoof &roof) {
    Mesh m;
    for (const RoofFace &face : roof.faces) {
        std::vector<Vec3f> corners;
        for (uint32_t c : face.corners) corners.push_back(toVec3f(roof.corners[c]));
        const RoofEdge &edge = roof.edges[face.edge];
        if (face.surface == RoofGableWall) {
            Vec3f along = normalize(lift(edge.end, 0) - lift(edge.start, 0));
            addFace(m, corners, wallUvPlane(edge.start, along, edge.perimeterBefore, roof.base), RoofGableWall);
            continue;
        }
        // CGAL's triangulation throws on outlines that cross themselves once rounded to floats.
        if (!isSimpleFromAbove(roof, face)) {
            return fmt::format("the roof face of edge ({} {}) – ({} {}) crosses itself seen from above", edge.start.x,
                               edge.start.y, edge.end.x, edge.end.y);
        }
        Vec3f normal = normalize(toVec3f(CGAL::ORIGIN + face.plane.orthogonal_vector()));
        size_t trianglesBefore = m.triangleCount();
        addProjectedFace(m, {corners}, normal, slopeUvPlane(corners), RoofCovering);
        if (m.triangleCount() - trianglesBefore != corners.size() - 2) {
            return fmt::format("the roof face of edge ({} {}) – ({} {}) does not triangulate", edge.start.x,
                               edge.start.y, edge.end.x, edge.end.y);
        }
    }
    return m;
}

}  // namespace veduta
