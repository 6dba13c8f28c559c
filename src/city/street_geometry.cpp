#include "city/street_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <tbb/parallel_for.h>

#include "city/footprint.h"
#include "city/street_index.h"
#include "city/street_pieces.h"
#include "city/street_regions.h"
#include "city/triangulation_inside.h"

namespace veduta {

namespace {

using Kernel = StreetKernel;
using Point = StreetPoint;
using Polygon = StreetPolygon;
using PolygonWithHoles = StreetPolygonWithHoles;
using PolygonSet = StreetPolygonSet;
// Street surfaces are triangulated in the exact kernel too (addRegion says why).
using ExactCdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_2<Kernel>,
        CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<bool, Kernel>>>>;

// The streets whose surface, `extra` wider on either side, may reach into the box around
// `outline`: far streets cannot change what is left of a block, and joining every street of a
// town for each of its blocks is what would make lots slow. The streets are asked of `index`
// where there is one, else measured one by one. Only the nodes they join are kept, in their
// order, so that the pieces (streetPieces: ribbons in street order, then joints in node order)
// are those of the whole network's node list, one for one.
StreetNetwork streetsNear(const std::vector<Vec2f> &outline, const StreetNetwork &network, float extra,
                          const StreetIndex *index) {
    Vec2f low = outline[0], high = outline[0];
    for (Vec2f p : outline) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    std::vector<uint32_t> candidates;
    if (index) {
        candidates = index->near(low, high, extra);
    } else {
        candidates.resize(network.streets.size());
        std::iota(candidates.begin(), candidates.end(), 0u);
    }
    StreetNetwork near{{}, {}, network.height};
    std::vector<uint32_t> nodes;
    for (uint32_t c : candidates) {
        const StreetNetwork::Street &s = network.streets[c];
        Vec2f a = network.nodes[s.from], b = network.nodes[s.to];
        float reach = s.width / 2 + extra;
        bool apart = std::min(a.x, b.x) - reach > high.x || std::max(a.x, b.x) + reach < low.x ||
            std::min(a.y, b.y) - reach > high.y || std::max(a.y, b.y) + reach < low.y;
        if (apart) continue;
        near.streets.push_back(s);
        nodes.insert(nodes.end(), {s.from, s.to});
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    auto renumbered = [&](uint32_t node) {
        return uint32_t(std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin());
    };
    for (StreetNetwork::Street &s : near.streets) s = {renumbered(s.from), renumbered(s.to), s.width};
    for (uint32_t node : nodes) near.nodes.push_back(network.nodes[node]);
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

// Vertical quads along the carriageway's boundary from its surface up to the sidewalk's, one
// for each of the tile's kerb segments (the road lies on their left).
void addKerbs(Mesh &mesh, const std::vector<StreetSegment> &kerbs, float low, float high) {
    for (const StreetSegment &kerb : kerbs) {
        Vec3f a = lifted(kerb.source(), low), b = lifted(kerb.target(), low);
        Vec3f along = b - a;
        if (length(along) <= 0) continue;
        // The kerb faces left, into the road.
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
}

// One tile's surfaces: its carriageway outside and inside the junctions, its sidewalks, its kerbs.
Mesh tileMesh(const StreetTileRegions &tile, float road, float pavement) {
    Mesh mesh;
    addRegion(mesh, tile.between, road, StreetCarriageway);
    addRegion(mesh, tile.junctions, road, StreetJunction);
    addRegion(mesh, tile.sidewalks, pavement, StreetSidewalk);
    addKerbs(mesh, tile.kerbs, road, pavement);
    return mesh;
}

// The tiles' meshes one after the other, in the tiles' order.
Mesh joined(std::vector<Mesh> &tiles) {
    if (tiles.size() == 1) return std::move(tiles[0]);
    Mesh mesh;
    for (const Mesh &tile : tiles) {
        auto base = uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), tile.positions.begin(), tile.positions.end());
        mesh.normals.insert(mesh.normals.end(), tile.normals.begin(), tile.normals.end());
        mesh.uvs.insert(mesh.uvs.end(), tile.uvs.begin(), tile.uvs.end());
        for (uint32_t i : tile.indices) mesh.indices.push_back(base + i);
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), tile.triangleMaterials.begin(),
                                      tile.triangleMaterials.end());
    }
    return mesh;
}

}  // namespace

std::vector<std::vector<Vec2d>> streetAreaPieces(const StreetNetwork &network, const StreetStyle &style) {
    std::vector<std::vector<Vec2d>> rings;
    for (const StreetRing &piece : streetPieces(network, style.sidewalkWidth)) {
        std::vector<Vec2d> &ring = rings.emplace_back();
        for (Vec2f v : piece) ring.push_back({v.x, v.y});
    }
    return rings;
}

std::vector<BuildableArea> buildableAreas(const std::vector<Vec2f> &block, const StreetNetwork &network,
                                          const StreetStyle &style, const StreetIndex *index) {
    PolygonSet streets = streetArea(streetsNear(block, network, style.sidewalkWidth, index), style.sidewalkWidth);
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

// Tile by tile (street_regions.h) on all cores, each tile's mesh made where its regions are;
// the meshes are joined in the tiles' order, so that the surface is the same on any number of
// threads.
Mesh streetGeometry(const StreetNetwork &network, const StreetStyle &style, size_t piecesPerTile) {
    StreetTiling tiling = streetTiling(network, style, piecesPerTile);
    float road = network.height + style.lift, pavement = road + style.kerbHeight;
    std::vector<Mesh> tiles(tiling.tiles.size());
    tbb::parallel_for(
        size_t(0), tiles.size(), [&](size_t t) { tiles[t] = tileMesh(streetTileRegions(tiling, t), road, pavement); },
        tbb::simple_partitioner());
    if (tiles.empty()) return {};
    return joined(tiles);
}

}  // namespace veduta
