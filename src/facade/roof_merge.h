// Merging the roofs of two connected modules (Finkenzeller 2008, §4.4.2, L976–988, Figs
// 4.28/4.29; digest-001 §2.3): when exactly one ridge touches the connection edge k and that
// ridge, extended beyond k, hits the neighbouring roof, the whole roof is extended to the hit:
// its two slopes at the ridge end run on over the neighbour until they meet its surface in
// valleys, and its interface at k goes. The neighbour's roof is left as it is; the part of it
// under the extension is hidden (the thesis changes only the marked roof).
//
// Choices where the thesis is open:
// * "Touches k" means the ridge end stands over the shared part of the two edges (L980's r ∈ k).
// * The valleys are where each extended slope meets the neighbour's surface, which is a polyline
//   wherever the surface bends under it; they run from the seam's corners to the new ridge end.
// * Extension needs what Fig 4.28 has, and otherwise the roofs stay as they are, with an outcome
//   saying why: the ridge end tops a gable triangle between two slopes (not a pyramid's apex, a
//   shed's corner or a fan of faces), the gable stands within the neighbour's edge, both modules
//   have the same eaves height, and the neighbour rises from its eaves at the gable's corners (a
//   slope, not an interface, stands there), so that the valleys start at those corners.
#pragma once

#include <cstddef>

#include "facade/general_roof.h"

namespace veduta {

enum class RoofMergeOutcome {
    BothRidgesTouch,       // no change (L980)
    NeitherRidgeTouches,   // no change (L982)
    RidgeMissesNeighbour,  // the extended ridge passes over or out of the neighbour: no change (L986)
    Extended,              // the touching roof now reaches the neighbour's surface
    NotAGableEnd,          // the touching ridge end tops no gable triangle: no change
    EavesDiffer,           // the modules' eaves heights differ: no change
    NeighbourRisesAtSeam,  // the neighbour is not at its eaves along the seam: no change
    GableWiderThanSeam,    // the gable at k reaches past the neighbour's edge: no change
};

// Merges the roofs of two modules connected along firstEdge of the first and secondEdge of the
// second (the edges run on one line in opposite directions and overlap: a KK or PP connection),
// changing the roof whose ridge is extended. A caller bug (edges that do not meet so) is an
// InternalError.
RoofMergeOutcome mergeRoofs(ModuleRoof &first, size_t firstEdge, ModuleRoof &second, size_t secondEdge);

}  // namespace veduta
