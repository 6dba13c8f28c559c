// The pieces whose union is a street surface: every street's ribbon and every node's round
// joint or bevel, and the round joints that bound the junctions, as counter-clockwise float
// rings. The union itself is street_regions.h's; the pieces are kept apart from it so that
// their boxes can be sorted into tiles before any exact arithmetic is done.
#pragma once

#include <vector>

#include "city/street_geometry.h"
#include "core/vecmath.h"

namespace veduta {

using StreetRing = std::vector<Vec2f>;

// Every street's ribbon, then every node's joint, each widened by `extra` on either side. Where
// a node joins two streets of one width that bend by less than 30°, a bevel fills the notch
// instead of a round joint: the two differ by under 1 − cos(θ/2) of the half width (3.4 % at
// 30°), and a street of many short segments (a curve, an OSM way) then brings a triangle per
// node into the union instead of a 16-gon overlapping its neighbours'. Streets of zero length
// are skipped. The rings of `extra` > 0 contain those of 0, bevel for bevel.
std::vector<StreetRing> streetPieces(const StreetNetwork &network, float extra);

// Where three or more streets meet, a round joint of kJunctionReach times the widest street's
// half width about the node, which takes in the square where the streets overlap and the
// corners where they turn: the junction is the carriageway within them.
std::vector<StreetRing> junctionJoints(const StreetNetwork &network);

}  // namespace veduta
