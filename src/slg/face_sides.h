// The four sides of a face and moving them (digest-003 §2.4, thesis L1650–1678): every gap of a
// plan — a street between districts, a house corridor, a sidewalk, the space round a building —
// is made by moving some sides of a face inwards, and a roof's overhang by moving them out.
#pragma once

#include <optional>
#include <vector>

#include "slg/plan_shape.h"

namespace veduta {

// A face's edges by side, each list in counter-clockwise order round the face.
struct FaceSides {
    std::vector<size_t> bottom;  // the front, from the left landmark to the right one
    std::vector<size_t> right;   // the straight run of edges that leaves the right landmark
    std::vector<size_t> top;     // everything else, possibly nothing
    std::vector<size_t> left;    // the straight run of edges that ends at the left landmark
};

// L1650–1666, for a face whose front is its edges 0 … frontEdges − 1, as a border face of a
// subdivision comes (its path starts at its left landmark). The right side takes the edges from
// the right landmark for as long as they run straight on; the left side likewise backwards from
// the left landmark, never taking an edge the right side took. A face closed by one edge
// behind its front (a chord between opposite landmarks) has that edge as both its sides.
FaceSides fourSides(const Polygon2d &face, size_t frontEdges);

// How far each side moves inwards, in metres; a negative distance moves it out.
struct SideDistances {
    double bottom = 0, right = 0, top = 0, left = 0;
};

// A shape whose edges were moved, and for each of its edges the edge of the original it came
// from (an edge can be split in two where a moved and an unmoved edge ran on in one line).
struct MovedShape {
    PlanShape shape;
    std::vector<size_t> source;
};

// Eq 24–25, as lines moved parallel: edge i moves `distances[i]` to its left (into the
// counter-clockwise shape), and each corner goes to where the moved lines of its two edges meet.
// So the ends of a moved side slide along the sides beside it (eq 24) and a corner within a side
// moves by d/sin(θ/2) along its bisector (the thesis's eq 25 is no miter; the digest's
// correction). Where two edges run on in one line and move by different distances, a short edge
// across joins them. Moved edges (and those joins) take the location `gap`; the rest keep
// theirs. None when the result is no longer a simple counter-clockwise shape whose edges keep
// their directions: the face is too small for the gap.
std::optional<MovedShape> moveEdges(const PlanShape &shape, const std::vector<double> &distances, EdgeLocation gap);

// moveEdges with one distance for all the edges of each side.
std::optional<MovedShape> moveSides(const PlanShape &shape, const FaceSides &sides, SideDistances distances,
                                    EdgeLocation gap);

// The sides of a shape after moveEdges, found again through the edges its edges came from.
FaceSides sidesAfterMove(const FaceSides &before, const std::vector<size_t> &source);

// The total length of some edges of a shape.
double sideLength(const PlanShape &shape, const std::vector<size_t> &edges);

}  // namespace veduta
