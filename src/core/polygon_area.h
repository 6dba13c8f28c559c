// The signed (shoelace) area of a ring of plane points: what the plan code (Schrader's eq 27)
// and the facade code (masonry pieces, casings) both measure outlines with.
#pragma once

#include <vector>

#include "core/vecmath.h"

namespace veduta {

// Positive when the points run counter-clockwise.
inline double signedArea(const std::vector<Vec2d> &ring) {
    double twice = 0;
    for (size_t i = 0; i < ring.size(); ++i) twice += cross(ring[i], ring[(i + 1) % ring.size()]);
    return twice / 2;
}

}  // namespace veduta
