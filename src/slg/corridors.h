// The corridors of a storey and an apartment (digest-003 §2.2 step 4, thesis Listing 3 and
// L1341–1385): the faces of a plan give up strips of their sides so that the space they leave
// — with the plan's inner faces — is a corridor from the entrance that reaches every apartment
// (the house corridor), or only the entrance's rooms and those that have a top (the apartment
// corridor: rooms may open into each other).
#pragma once

#include <vector>

#include "slg/face_sides.h"
#include "slg/subdivision.h"

namespace veduta {

enum class CorridorKind : uint8_t { House, Apartment };

struct CorridorParameters {
    CorridorKind kind = CorridorKind::House;
    double width = 1.5;          // the gap width of Tables 13 and 16
    double entranceWidth = 1.0;  // a door from the corridor into a face must fit on its free edge
};

struct CorridorPlan {
    // The border faces of the subdivision after their sides moved, in its order, with their sides.
    // The corridor is what they leave of the outline (corridorPieces).
    std::vector<PlanShape> faces;
    std::vector<FaceSides> sides;
    // House corridors: the faces whose free edges onto the corridor are all shorter than the
    // entrance width after every side that could move did.
    int unreached = 0;
    // Faces whose side could not move by the corridor width without folding: kept as they were.
    int tooSmall = 0;
};

// Listing 3 on a subdivision of `outline`, with the corridor's entrance at landmark `entrance`:
// the two faces beside it move the side that holds it by width/2, so the corridor starts there
// as wide as the others. Then (house corridor) every other face that has no free edge as long
// as the entrance width — an edge on neither the outline nor another face — moves the side of
// top, left and right with the most free length by the width (the shortest on a tie), until it
// has one; the apartment corridor moves only the tops.
CorridorPlan makeCorridor(const Subdivision &subdivision, SlgNodeId entrance, const CorridorParameters &parameters);

// The outline less the faces — a corridor, or what a plan's faces leave — one polygon (with its
// holes' outlines after it, clockwise) per connected piece. CGAL's exact Booleans: the costliest
// step of a plan, so made only where the geometry is wanted.
std::vector<std::vector<Polygon2d>> corridorPieces(const Polygon2d &outline, const std::vector<PlanShape> &faces);

// Of each edge of face `f`, the length on neither the outline nor another face.
std::vector<double> freeLengths(const std::vector<PlanShape> &faces, size_t f, const Polygon2d &outline);

}  // namespace veduta
