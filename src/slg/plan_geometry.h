// The plane geometry of Schrader's Spatial Landmark Graph (digest-003 §2.5), in double: plans of
// blocks, lots, storeys and rooms in metres. The orientation and containment tests go through
// CGAL's exact predicates, so that a point on a line or a collinear corner is decided the same
// way every time instead of folding on a rounding (the thesis's float tests do).
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "core/polygon_area.h"
#include "core/vecmath.h"

namespace veduta {

inline Vec2d normalized(Vec2d v) { return v * (1 / length(v)); }
// The inward normal of an edge of a counter-clockwise outline: the edge turned left (eq 8).
inline Vec2d leftNormal(Vec2d v) { return {-v.y, v.x}; }

using Polygon2d = std::vector<Vec2d>;

// Eq 27, the signed shoelace area, is core's signedArea (core/polygon_area.h).
// Eq 28: the mean of the points (not the area's centroid), the thesis's centre of a city and
// the apex of a tent roof.
Vec2d vertexMean(const Polygon2d &polygon);
// Eq 29: the angle between two directions in degrees, in [0, 180].
double angle180(Vec2d a, Vec2d b);
// Eq 30: the angle turned from direction a to direction b, counter-clockwise, in [0, 360).
double angle360(Vec2d a, Vec2d b);

enum class Turn { Left, Straight, Right };
// Which way the path p → q → r turns at q, decided exactly.
Turn turnAt(Vec2d p, Vec2d q, Vec2d r);
// Whether the path p → q → r goes straight on at q, to within the rounding of points that are
// crossings of lines worked out in double (a turn under 10⁻⁹ radians): the crossings along one
// ray of a plan lie in its line only to a rounding, which an exact test would take for corners.
bool goesStraightOn(Vec2d p, Vec2d q, Vec2d r);
// The indices of the points where a polygon turns (not goesStraightOn), in order.
std::vector<size_t> turningPoints(const Polygon2d &polygon);
// The index of the point that starts the polygon's longest edge (the first of equal ones).
size_t longestEdge(const Polygon2d &polygon);
// Whether the corner at points[i] of a counter-clockwise polygon is reflex (turns right).
bool isReflexCorner(const Polygon2d &ccw, size_t i);

// Eq 31–32: the parameters s, t at which p + s·u and q + t·v meet; none when parallel.
struct LineHit {
    double s = 0, t = 0;
};
std::optional<LineHit> intersectLines(Vec2d p, Vec2d u, Vec2d q, Vec2d v);

enum class Side { Inside, Boundary, Outside };
// Eq 33–34, exactly: where a point lies with respect to a simple polygon of either orientation.
Side sideOf(const Polygon2d &polygon, Vec2d point);

// How far a point lies from the boundary of a polygon, and how far outside it: 0 when it is
// inside or on it.
double distanceToBoundary(const Polygon2d &polygon, Vec2d point);
double distanceOutside(const Polygon2d &polygon, Vec2d point);

// Whether a polygon is simple (no two edges meet except neighbours at their shared point).
bool isSimple(const Polygon2d &polygon);

}  // namespace veduta
