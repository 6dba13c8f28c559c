// The levels of Schrader's hierarchy (digest-003 §1, L2459–2483) and what each makes of the
// edges of its plan (§2.2 step 7, L1458–1479).
#pragma once

#include <cstdint>

#include "slg/subdivision.h"

namespace veduta {

// The levels that subdivide a plan. A lot is not subdivided (its sidewalk and building are
// moved sides, building_plan.h); Building is Table 13's plan, the one every storey shares.
enum class PlanLevel : uint8_t { City, District, Block, Building, Apartment };
inline constexpr int kPlanLevels = 5;

// Gives the edges of a level's subdivision their locations. City and District: every edge a
// street. Below, outer edges keep what the parent's face gave them (a lot's sides are already
// neighbour areas of its block, an apartment's walls on the shell the building's), and an
// inner edge two faces share becomes the level's neighbour (neighbour area, neighbour
// apartment, neighbour room), one only one face uses its gap (gap, house corridor, apartment
// corridor): the corridor a gap step makes there runs along it.
void labelEdges(Subdivision &subdivision, PlanLevel level);

}  // namespace veduta
