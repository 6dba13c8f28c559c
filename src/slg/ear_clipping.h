// The triangulation of the thesis (digest-003 §3.4, L2261–2284): ear clipping of one edge loop
// with no points inside, for floors, ceilings, flat roofs and block surfaces.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "slg/plan_geometry.h"

namespace veduta {

// The n − 2 triangles of a simple counter-clockwise polygon, as indices into it, each
// counter-clockwise: an ear is a convex corner whose triangle holds no other corner (decided
// exactly). Points on a straight line make triangles of no area where nothing else is left.
std::vector<std::array<uint32_t, 3>> clipEars(const Polygon2d &ccw);

}  // namespace veduta
