// Schrader's floor-plan extension (digest-003 §3.1, thesis L1944–2020): before anything is built
// in 3D, doors, windows and the stairwell's entrance go into a plan as "a replacement grammar on
// edges" (L1980). A wall edge is split (eq 26) into [margin][opening][rest] and the opening's
// piece takes a door's or window's location; the rest keeps the wall's. Doors go in first, so a
// window never takes a door's piece (L1955). See docs/plan-extension.md.
#pragma once

#include <cstdint>
#include <optional>

#include "slg/slg_graph.h"
#include "slg/storey_parameters.h"
#include "slg/subdivision.h"

namespace veduta {

// A kind of door (L1957–1972): the location of the walls it may go in and the one its piece
// takes, its width and how near at least it comes to the wall's ends (the neighbouring walls).
struct DoorRule {
    EdgeLocation wall = EdgeLocation::Street;
    EdgeLocation door = EdgeLocation::MainEntrance;
    double width = 1;
    double wallDistance = 0;
    DoorAlignment alignment = DoorAlignment::Centre;
};

// The house door: one per building, in the ground floor's house corridor, centred in its outer
// wall towards `facing` (the street, or the gap behind when shops take the front, eq 58).
DoorRule houseDoor(double width, double wallDistance, EdgeLocation facing);
// An apartment's door: centred in its corridor's wall to the house corridor.
DoorRule apartmentDoor(double width, double wallDistance);
// A room's door: centred in its wall to the apartment's corridor.
DoorRule roomDoor(double width, double wallDistance);
// A shop's or restaurant's own door: in its street wall, left, centred or right.
DoorRule shopDoor(double width, double wallDistance, DoorAlignment alignment);
// The stairwell's entrance: centred in its wall to the house corridor (L2018).
DoorRule stairDoor(double width, double wallDistance);

enum class DoorOutcome : uint8_t {
    Placed,
    NoWall,        // no edge has the rule's wall location
    WallTooShort,  // the longest is shorter than the width and twice the wall distance
};

struct DoorPlacement {
    DoorOutcome outcome = DoorOutcome::NoWall;
    SlgEdgeId door = kNoSlgId;  // the door's piece, when placed
};

// L1976–1981: takes the longest edge of the rule's wall location (the first of equal ones) and
// cuts the door's piece out of it. In the whole graph an edge's left end is its start; in a
// face, the node its counter-clockwise path reaches first. The face's path is brought up to date
// before and after; other paths through the split edge need followSplits.
DoorPlacement insertDoor(SlgGraph &graph, const DoorRule &rule);
DoorPlacement insertDoor(SlgGraph &graph, SlgPath &face, const DoorRule &rule);

// A storey's window tuple (§4.6) as far as the plan needs it: the width, how they are arranged,
// their spacing (ignored when contiguous), the least margin to the wall's ends and how many at
// most per wall (none: as many as fit).
struct WindowRule {
    double width = 1;
    WindowArrangement arrangement = WindowArrangement::Separated;
    double spacing = 1;
    double wallDistance = 1;
    std::optional<int> count;
};

// The number of windows of the rule that fit on a wall of this length, at most its count: n
// windows and the n − 1 spacings between them leave at least the wall distance at both ends.
int windowsThatFit(const WindowRule &rule, double wallLength);

struct WindowPlacement {
    int windows = 0;        // window pieces made
    int walls = 0;          // outer street and gap walls looked at
    int wallsTooShort = 0;  // of them, the ones no window fits on
};

// L2001–2005: on every outer edge located at a street or a gap (never a neighbour's, nor a
// door's piece), the windows that fit, centred as a group, each piece relabelled
// WindowToStreet or WindowToGap after its wall. In a face, only the face's edges, and its path
// is brought up to date.
WindowPlacement insertWindows(SlgGraph &graph, const WindowRule &rule);
WindowPlacement insertWindows(SlgGraph &graph, SlgPath &face, const WindowRule &rule);

// The stairwell of L2009–2020, in buildings of at least this many storeys (L2011; L2415's
// "more than two" would leave two-storey houses without a way up).
inline constexpr int kStairwellMinimumStoreys = 2;

// Which room may be the stairwell: a quadrilateral whose shortest side is at least `sideRatio`
// of its longest ("four sides of about equal length"), of at least `minimumArea` (Table 12's 5 m²),
// with a wall to the house corridor that takes the stair door (by default Table 15's inner door,
// 1.5 m; its tuple has no wall distance).
struct StairwellRule {
    double minimumArea = 5;
    double sideRatio = 0.75;
    DoorRule door = stairDoor(1.5, 0);
};

// Picks the smallest room that may be the stairwell (the first of equal ones) among the border
// faces of an apartment's plan and puts the stair door in it, bringing every face's path up to
// date. Returns the face's index; none when the building is too low or no room qualifies.
std::optional<size_t> insertStairwell(Subdivision &plan, int storeys, const StairwellRule &rule);

}  // namespace veduta
