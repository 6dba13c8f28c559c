// A building's ground plan (Bilke's lot footprint, Bilke 2009, §2.1.2, §11): the polygon that
// start shapes and roofs are built on.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"

namespace veduta {

// A building's ground plan: a simple polygon, counter-clockwise seen from above, in world x/y
// metres, at ground height `base`; edge i runs from points[i] to points[(i+1) % n].
struct Footprint {
    std::vector<Vec2f> points;
    std::vector<bool> streetEdges;  // one per edge; true where the edge faces a street
    float base = 0;

    size_t edgeCount() const { return points.size(); }
    Vec2f edgeStart(size_t edge) const { return points[edge]; }
    Vec2f edgeEnd(size_t edge) const { return points[(edge + 1) % points.size()]; }
    float edgeLength(size_t edge) const;
    // Metres along the outline from point 0 to the start of `edge`: the u of the walls' texture
    // there, so that it runs on around the corners (and up into the gables).
    float perimeterBefore(size_t edge) const;
    // Horizontal unit vectors: along the edge, and away from the building (to the edge's right,
    // since the ring runs counter-clockwise).
    Vec3f edgeDirection(size_t edge) const;
    Vec3f outwardNormal(size_t edge) const;
};

// The most points an outline (footprint, block) may have: far more than any building or
// block of a real town, and few enough that the checks and cuts stay fast.
inline constexpr size_t kMaxOutlinePoints = 20000;

// A footprint point at height z.
inline Vec3f lift(Vec2f p, float z) { return {p.x, p.y, z}; }

// Checks a footprint from user input: ≥ 3 finite points, none repeated, simple (no edge
// crosses, touches or runs back along another, so no collinear spikes and no zero area). A
// clockwise one is reversed (with its street flags) and a warning "file:line:col: message"
// returned. Empty street flags mean no street edges. Throws InputError(loc, …) on the rest.
std::optional<std::string> normaliseFootprint(Footprint &footprint, const FileLoc &loc);

// Polygon helpers on the same conventions (a closed ring of points, edge i from point i to
// point i + 1), with CGAL's exact predicates.
bool isSimplePolygon(std::span<const Vec2f> polygon);
bool isCounterClockwise(std::span<const Vec2f> polygon);  // of a simple polygon
// The area of a simple polygon, positive when it runs counter-clockwise; in double precision.
float signedArea(std::span<const Vec2f> polygon);
// Whether simple polygon `inner` lies inside simple polygon `outer` without touching its outline.
bool liesInside(std::span<const Vec2f> inner, std::span<const Vec2f> outer);
// Each edge of a ring moved `distance` to its right (outwards on a counter-clockwise ring;
// negative: to its left) and neighbouring moved lines intersected: corner i moves by
// distance · (a + b) / (1 + a·b), a and b the right-hand normals of the edges meeting there,
// which lies on both moved lines (and is distance · a where the edges run straight on). The
// result may cross itself where the ring cannot take the distance.
std::vector<Vec2f> offsetPolygon(std::span<const Vec2f> ring, float distance);
// The same with a distance of its own for each edge (edge i from point i to point i + 1):
// corner i is where the moved lines of edges i − 1 and i meet.
std::vector<Vec2f> offsetPolygon(std::span<const Vec2f> ring, std::span<const float> distances);
// The distance from `p` to the segment from `a` to `b` (to `a` when the two coincide), worked
// out in double precision.
double distanceToSegment(Vec2f p, Vec2f a, Vec2f b);
// Whether `p` lies inside `polygon`, on its outline, or within `tolerance` metres of it.
bool covers(std::span<const Vec2f> polygon, Vec2f p, double tolerance);
// The first edge of simple polygon `inner` that leaves `outer`, give or take `tolerance`: its
// middle lies outside, or it crosses an edge of `outer` with both ends of either edge farther
// than `tolerance` from the other. None when `inner` lies in `outer` (its corners are not
// checked: see covers).
std::optional<size_t> edgeLeaving(std::span<const Vec2f> inner, std::span<const Vec2f> outer, double tolerance);
// The centre of area of a simple polygon.
Vec2f areaCentroid(std::span<const Vec2f> polygon);
// Whether simple polygons `a` and `b` neither touch nor lie one inside the other.
bool areDisjoint(std::span<const Vec2f> a, std::span<const Vec2f> b);
// Triangles covering a simple counter-clockwise polygon: n − 2 of them, three indices into the
// polygon each, counter-clockwise (CGAL's constrained Delaunay triangulation, so no new points).
std::vector<uint32_t> triangulatePolygon(std::span<const Vec2f> polygon);
// The same for a polygon with holes: rings[0] the outline, the rest holes inside it, apart from
// each other; indices count through the rings in order (ring 1 starts after ring 0's points).
std::vector<uint32_t> triangulatePolygonWithHoles(std::span<const std::vector<Vec2f>> rings);

}  // namespace veduta
