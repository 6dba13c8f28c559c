#include "city/street_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <map>
#include <optional>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include "city/footprint.h"
#include "city/triangulation_inside.h"

namespace veduta {

namespace {

// Exact constructions: the unions and differences of many overlapping ribbons must not fail.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;
// Street surfaces are triangulated in the exact kernel too (addRegion says why).
using ExactCdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_2<Kernel>,
        CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<bool, Kernel>>>>;

// What of `a` lies outside `b`, where `b` lies inside `a`: their symmetric difference. CGAL 5.5's
// difference leaves, on some street networks, an arrangement with a face of two outer
// boundaries (its own assertion catches it in a checked build:
// fuzz/regressions/osm/difference_face_of_two_outer_boundaries.osm), where the symmetric
// difference of the same sets does not.
void cutOut(PolygonSet &a, const PolygonSet &b) { a.symmetric_difference(b); }

Polygon ribbon(Vec2f a, Vec2f b, float halfWidth) {
    float dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    float nx = -dy / length * halfWidth, ny = dx / length * halfWidth;
    Polygon p;
    p.push_back(Point(a.x - nx, a.y - ny));
    p.push_back(Point(b.x - nx, b.y - ny));
    p.push_back(Point(b.x + nx, b.y + ny));
    p.push_back(Point(a.x + nx, a.y + ny));
    return p;
}

// A round joint at a node, so that streets meeting at any angle leave no notch.
Polygon joint(Vec2f centre, float radius) {
    Polygon p;
    // The polygon circumscribes the circle, so that it covers the ribbons' corners.
    float r = radius / std::cos(kPi / kStreetJointSides);
    for (int k = 0; k < kStreetJointSides; ++k) {
        float a = 2 * kPi * float(k) / kStreetJointSides;
        p.push_back(Point(centre.x + r * std::cos(a), centre.y + r * std::sin(a)));
    }
    return p;
}

// The triangle that fills the notch on the outside of a bend at `node`, between the ends of
// the ribbons from `from` and to `to`; nothing when they run straight on.
std::optional<Polygon> bevel(Vec2f from, Vec2f node, Vec2f to, float halfWidth) {
    Vec2f in = node - from, out = to - node;
    float turn = in.x * out.y - in.y * out.x;
    if (std::abs(turn) <= 1e-6f * std::hypot(in.x, in.y) * std::hypot(out.x, out.y)) return std::nullopt;
    // The outside of a left turn is on the right.
    float side = turn > 0 ? -1.0f : 1.0f;
    auto corner = [&](Vec2f d) {
        float length = std::hypot(d.x, d.y);
        return Point(node.x + side * -d.y / length * halfWidth, node.y + side * d.x / length * halfWidth);
    };
    // In float the corners may fall onto the node or onto one line with it (a tiny width, far
    // coordinates): such a bevel covers nothing, and is no polygon CGAL takes.
    Point apex(node.x, node.y), a = corner(in), b = corner(out);
    switch (CGAL::orientation(apex, a, b)) {
    case CGAL::COLLINEAR: return std::nullopt;
    case CGAL::CLOCKWISE: std::swap(a, b); break;
    default: break;
    }
    Polygon p;
    p.push_back(apex);
    p.push_back(a);
    p.push_back(b);
    return p;
}

// Streets meet at a node: its ribbons' ends, the widest half width among them, and for the
// node's bevel the other ends of its (at most two) streets.
struct NodeStreets {
    int count = 0;
    float widestHalf = 0;
    bool sameWidth = true;
    uint32_t others[2] = {0, 0};
};

// Every street's ribbon, then every node's joint, each widened by `extra` on either side.
// Where a node joins two streets of one width that bend by less than kBevelTurnDegrees, a
// bevel fills the notch instead of a round joint: the two differ by under 1 − cos(θ/2) of the
// half width (3.4 % at 30°), and a street of many short segments (a curve, an OSM way) then
// brings a triangle per node into the union instead of a 16-gon overlapping its neighbours'.
std::vector<Polygon> streetPieces(const StreetNetwork &network, float extra) {
    constexpr float kBevelTurnDegrees = 30;
    const float bevelCos = std::cos(kBevelTurnDegrees * kPi / 180);
    std::vector<Polygon> pieces;
    std::vector<NodeStreets> at(network.nodes.size());
    auto meet = [&](uint32_t node, uint32_t other, float half) {
        NodeStreets &n = at[node];
        if (n.count > 0 && n.widestHalf != half) n.sameWidth = false;
        if (n.count < 2) n.others[n.count] = other;
        ++n.count;
        n.widestHalf = std::max(n.widestHalf, half);
    };
    for (const StreetNetwork::Street &s : network.streets) {
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
        if (a.x == b.x && a.y == b.y) continue;
        float half = s.width / 2 + extra;
        pieces.push_back(ribbon(a, b, half));
        // Widths compare without `extra`, so that the sidewalks' pieces are the carriageway's
        // widened, bevel for bevel, and contain them (cutOut relies on it).
        meet(s.from, s.to, s.width / 2);
        meet(s.to, s.from, s.width / 2);
    }
    for (size_t n = 0; n < network.nodes.size(); ++n) {
        const NodeStreets &node = at[n];
        if (node.count == 0) continue;
        Vec2f from = network.nodes[node.others[0]], centre = network.nodes[n], to = network.nodes[node.others[1]];
        Vec2f in = centre - from, out = to - centre;
        bool gentle = node.count == 2 && node.sameWidth &&
            in.x * out.x + in.y * out.y >= bevelCos * std::hypot(in.x, in.y) * std::hypot(out.x, out.y);
        if (!gentle) {
            pieces.push_back(joint(centre, node.widestHalf + extra));
        } else if (std::optional<Polygon> b = bevel(from, centre, to, node.widestHalf + extra)) {
            pieces.push_back(std::move(*b));
        }
    }
    return pieces;
}

// The union of every street's ribbon and joint, each widened by `extra` on either side. All
// at once: CGAL joins a range by divide and conquer, where joining piece by piece would
// sweep the growing union once per piece, quadratic in the streets of a town.
PolygonSet streetArea(const StreetNetwork &network, float extra) {
    std::vector<Polygon> pieces = streetPieces(network, extra);
    PolygonSet area;
    area.join(pieces.begin(), pieces.end());
    return area;
}

// The streets whose surface, `extra` wider on either side, may reach into the box around
// `outline`: far streets cannot change what is left of a block, and joining every street of a
// town for each of its blocks is what would make lots slow. Node indices stay as they are.
StreetNetwork streetsNear(const std::vector<Vec2f> &outline, const StreetNetwork &network, float extra) {
    Vec2f low = outline[0], high = outline[0];
    for (Vec2f p : outline) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    StreetNetwork near{network.nodes, {}, network.height};
    for (const StreetNetwork::Street &s : network.streets) {
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
        float reach = s.width / 2 + extra;
        bool apart = std::min(a.x, b.x) - reach > high.x || std::max(a.x, b.x) + reach < low.x ||
            std::min(a.y, b.y) - reach > high.y || std::max(a.y, b.y) + reach < low.y;
        if (!apart) near.streets.push_back(s);
    }
    return near;
}

Vec3f lifted(const Point &p, float z) { return {float(CGAL::to_double(p.x())), float(CGAL::to_double(p.y())), z}; }

Vec2f toFloat(const Point &p) { return {float(CGAL::to_double(p.x())), float(CGAL::to_double(p.y()))}; }

// Whether two rounded corners are one: within a few float steps of each other.
bool sameCorner(Vec2f a, Vec2f b) {
    auto close = [](float u, float v) {
        return std::abs(u - v) <=
            4 * std::numeric_limits<float>::epsilon() * std::max({1.0f, std::abs(u), std::abs(v)});
    };
    return close(a.x, b.x) && close(a.y, b.y);
}

// The outline in float. Corners of an exact union can lie closer than a float can tell apart:
// a corner that rounds onto (or next to) the one before it is left out, and so is a sliver
// narrower than a few float steps, which rounds to a spike out to a corner and back (a wedge the
// streets leave at a bend of a ring road).
std::vector<Vec2f> toRing(const Polygon &polygon) {
    std::vector<Vec2f> ring;
    for (auto v = polygon.vertices_begin(); v != polygon.vertices_end(); ++v) ring.push_back(toFloat(*v));
    auto same = sameCorner;
    for (bool changed = true; changed && ring.size() >= 3;) {
        changed = false;
        for (size_t i = 0; i < ring.size() && ring.size() >= 3; ++i) {
            size_t next = (i + 1) % ring.size(), after = (i + 2) % ring.size();
            if (same(ring[i], ring[next])) {
                ring.erase(ring.begin() + std::ptrdiff_t(next));
                changed = true;
            } else if (same(ring[i], ring[after])) {
                // i, spike, i again: the spike and the repeat go.
                ring.erase(ring.begin() + std::ptrdiff_t(std::max(next, after)));
                ring.erase(ring.begin() + std::ptrdiff_t(std::min(next, after)));
                changed = true;
            }
        }
    }
    return ring;
}

// The region's triangles, facing up, at height z. They are found in exact arithmetic and only
// then rounded: rounded first, two corners of the exact union may fall on one float point, or
// outlines cross, and no triangulation of float outlines can take that.
void addRegion(Mesh &mesh, const PolygonSet &region, float z, StreetSurface surface) {
    std::vector<PolygonWithHoles> parts;
    region.polygons_with_holes(std::back_inserter(parts));
    for (const PolygonWithHoles &part : parts) {
        ExactCdt cdt;
        auto constrain = [&](const Polygon &ring) {
            cdt.insert_constraint(ring.vertices_begin(), ring.vertices_end(), true);
        };
        constrain(part.outer_boundary());
        for (const Polygon &hole : part.holes()) constrain(hole);
        markInside(cdt);
        std::map<ExactCdt::Vertex_handle, uint32_t> index;
        for (ExactCdt::Face_handle f : cdt.finite_face_handles()) {
            if (!f->info()) continue;
            for (int k = 0; k < 3; ++k) {
                auto [at, added] = index.try_emplace(f->vertex(k), uint32_t(mesh.positions.size()));
                if (added) {
                    Vec2f p = toFloat(f->vertex(k)->point());
                    mesh.positions.push_back({p.x, p.y, z});
                    mesh.normals.push_back({0, 0, 1});
                    mesh.uvs.push_back(p);
                }
                mesh.indices.push_back(at->second);
            }
            mesh.triangleMaterials.push_back(surface);
        }
    }
}

// Vertical quads along the carriageway's boundary from its surface up to the sidewalk's.
void addKerbs(Mesh &mesh, const PolygonSet &carriageway, float low, float high) {
    std::vector<PolygonWithHoles> parts;
    carriageway.polygons_with_holes(std::back_inserter(parts));
    auto ring = [&](const Polygon &polygon) {
        for (auto e = polygon.edges_begin(); e != polygon.edges_end(); ++e) {
            Vec3f a = lifted(e->source(), low), b = lifted(e->target(), low);
            Vec3f along = b - a;
            if (length(along) <= 0) continue;
            // The region lies left of its boundary's edges (outer ring CCW, holes CW): the kerb
            // faces left, into the road.
            Vec3f inward = normalize(Vec3f(-along.y, along.x, 0));
            auto base = uint32_t(mesh.positions.size());
            float u0 = 0, u1 = length(along);
            Vec3f corners[4] = {a, b, b + Vec3f(0, 0, high - low), a + Vec3f(0, 0, high - low)};
            Vec2f uvs[4] = {{u0, 0}, {u1, 0}, {u1, high - low}, {u0, high - low}};
            for (int k = 0; k < 4; ++k) {
                mesh.positions.push_back(corners[k]);
                mesh.normals.push_back(inward);
                mesh.uvs.push_back(uvs[k]);
            }
            // Seen from the road (from `inward`), b is on the left of a: wind a, top-a, top-b, b.
            mesh.indices.insert(mesh.indices.end(), {base, base + 3, base + 2, base, base + 2, base + 1});
            mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {StreetKerb, StreetKerb});
        }
    };
    for (const PolygonWithHoles &part : parts) {
        ring(part.outer_boundary());
        for (const Polygon &hole : part.holes()) ring(hole);
    }
}

Polygon toPolygon(const std::vector<Vec2f> &ring) {
    Polygon p;
    for (Vec2f v : ring) p.push_back(Point(v.x, v.y));
    return p;
}

}  // namespace

std::vector<std::vector<Vec2d>> streetAreaPieces(const StreetNetwork &network, const StreetStyle &style) {
    std::vector<std::vector<Vec2d>> rings;
    for (const Polygon &piece : streetPieces(network, style.sidewalkWidth)) {
        std::vector<Vec2d> &ring = rings.emplace_back();
        for (auto v = piece.vertices_begin(); v != piece.vertices_end(); ++v)
            ring.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
    }
    return rings;
}

std::vector<BuildableArea> buildableAreas(const std::vector<Vec2f> &block, const StreetNetwork &network,
                                          const StreetStyle &style) {
    PolygonSet streets = streetArea(streetsNear(block, network, style.sidewalkWidth), style.sidewalkWidth);
    PolygonSet left(toPolygon(block));
    left.difference(streets);
    std::vector<PolygonWithHoles> parts;
    left.polygons_with_holes(std::back_inserter(parts));
    std::vector<BuildableArea> areas;
    for (const PolygonWithHoles &part : parts) {
        BuildableArea area;
        area.outline = toRing(part.outer_boundary());
        if (area.outline.size() < 3) continue;  // a sliver narrower than a float step
        size_t n = area.outline.size();
        for (size_t i = 0; i < n; ++i) {
            Vec2f a = area.outline[i], b = area.outline[(i + 1) % n];
            float dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
            // Half a metre outward from the edge's middle: on a sidewalk if the edge faces a street.
            Point probe((a.x + b.x) / 2 + dy / length * 0.5f, (a.y + b.y) / 2 - dx / length * 0.5f);
            area.streetEdges.push_back(streets.oriented_side(probe) != CGAL::ON_NEGATIVE_SIDE);
        }
        areas.push_back(std::move(area));
    }
    return areas;
}

// The crossings: where three or more streets meet, the carriageway within kJunctionReach times
// the widest street's half width of the node, which takes in the square where the streets
// overlap and the corners where they turn.
PolygonSet junctionArea(const StreetNetwork &network, const PolygonSet &carriageway) {
    std::vector<int> streetsAt(network.nodes.size(), 0);
    std::vector<float> widestHalf(network.nodes.size(), 0.0f);
    for (const StreetNetwork::Street &s : network.streets) {
        if (network.nodes[s.from].x == network.nodes[s.to].x && network.nodes[s.from].y == network.nodes[s.to].y)
            continue;
        for (uint32_t node : {s.from, s.to}) {
            ++streetsAt[node];
            widestHalf[node] = std::max(widestHalf[node], s.width / 2);
        }
    }
    std::vector<Polygon> squares;
    for (size_t n = 0; n < network.nodes.size(); ++n)
        if (streetsAt[n] >= 3) squares.push_back(joint(network.nodes[n], kJunctionReach * widestHalf[n]));
    PolygonSet junctions;
    junctions.join(squares.begin(), squares.end());
    junctions.intersection(carriageway);
    return junctions;
}

Mesh streetGeometry(const StreetNetwork &network, const StreetStyle &style) {
    Mesh mesh;
    PolygonSet carriageway = streetArea(network, 0);
    PolygonSet sidewalks = streetArea(network, style.sidewalkWidth);
    cutOut(sidewalks, carriageway);
    float road = network.height + style.lift, pavement = road + style.kerbHeight;
    PolygonSet junctions = junctionArea(network, carriageway), between = carriageway;
    cutOut(between, junctions);
    addRegion(mesh, between, road, StreetCarriageway);
    addRegion(mesh, junctions, road, StreetJunction);
    addRegion(mesh, sidewalks, pavement, StreetSidewalk);
    addKerbs(mesh, carriageway, road, pavement);
    return mesh;
}

}  // namespace veduta
