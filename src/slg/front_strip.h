// A strip along the front of a face (digest-003 §2.2 step 4, L1387–1425): a lot's sidewalk,
// and the band behind it to the depth of the shorter side, in which its building stands.
#pragma once

#include <optional>
#include <vector>

#include "slg/face_sides.h"

namespace veduta {

struct FrontStrip {
    // The front of the face (its edges 0 … k − 1, as in the face), then the strip's right end,
    // its back counter-clockwise, and its left end. The back takes the location `back`, the ends
    // the locations of the face's sides there.
    PlanShape strip;
    FaceSides stripSides;
    // The face behind the strip, whose front is the strip's back, with its sides; none where the
    // strip takes the whole face.
    std::optional<PlanShape> behind;
    FaceSides behindSides;
    // The strip cut into one quad per front edge (L1391), each counter-clockwise.
    std::vector<Polygon2d> quads;
};

// The strip of the given depth along the front of a face; `back` is what its back edges face
// (the lot behind a sidewalk is the street's side: EdgeLocation::Street). Its back runs at
// `depth` from the front, and its ends on the lines of the sides. None when the face is not
// that deep everywhere along its front (the strip would leave it).
std::optional<FrontStrip> cutFrontStrip(const PlanShape &face, const FaceSides &sides, double depth, EdgeLocation back);

}  // namespace veduta
