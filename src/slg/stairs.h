// The stairs in a stairwell (digest-003 §3.2 and §3.5, L2009–2020): a straight flight of steps up
// one storey along the room's longest side. The thesis draws a landing stair without steps, at
// most five polygons; here each step is a riser and a tread, so that the stairs read as stairs
// from the nearest level on.
#pragma once

#include <optional>

#include "slg/plan_geometry.h"

namespace veduta {

// Equal steps up one storey: step i (from 0) rises from i·riser to (i + 1)·riser, its riser
// standing i·going up the flight from the foot and its tread reaching one going further. The
// last tread is the floor above.
struct Flight {
    Vec2d foot;    // where the first riser meets the wall the flight runs along
    Vec2d up;      // the way up, along that wall (a unit vector)
    Vec2d across;  // from the wall into the room (a unit vector, up turned left)
    double width = 0, going = 0, riser = 0;
    int risers = 0;

    // The point `along` metres up the flight from the foot and `into` metres from the wall.
    Vec2d at(double along, double into) const { return foot + up * along + across * into; }
};

// The flight up `height` along the longest straight side of a counter-clockwise room (the floor
// inside its walls), its foot a going from as near the side's start as its width allows: risers
// of about 0.18 m, a going that makes Blondel's pace of 0.63 m with two of them or less where the
// side is shorter, 1 m wide. None where no such flight fits in the room beside that side.
std::optional<Flight> straightFlight(const Polygon2d &room, double height);

// Step i's tread, counter-clockwise from its front edge's end at the wall.
Polygon2d tread(const Flight &flight, int step);

}  // namespace veduta
