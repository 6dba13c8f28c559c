// Consoles under a cornice (digest-001 §2.6, Def 5.10, L1165–1172): an external mesh, the same
// for the whole cornice, set on rectangles spaced evenly along the run, `spacing` metres between
// their centres. This places them: one transform per console, for an Embree instance of the
// console's mesh.
//
// The console's model is authored in a unit box: x in [-0.5, 0.5] to the right seen from the
// front, y in [0, 1] up, z in [0, 1] out of the wall toward the viewer (right-handed, so no
// instance is mirrored). Each transform maps that box onto the console's rectangle on the wall
// face (the plane of the wall direction and up, L1168) and out of it.
//
// Choices where the thesis is open:
//   * The rectangle's breite and hoehe are in the profile's units and scale with it (L1168);
//     `abstand` is in metres (digest §8 row 11 reads it so).
//   * The start offset is not given [GAP]. Each straight edge of the run gets its own pattern,
//     centred on the edge, with as many consoles as fit while none comes closer to an end of the
//     edge than half its width; at a concave corner, at either end of the edge, the margin grows
//     by the console's depth times the mitre's slope, so that no console crosses the mitre plane
//     and the consoles of the two walls do not run into each other. A convex corner's mitre lies
//     beyond the edge and adds nothing. A console never straddles a corner.
//   * The rectangle stands on the partition's bottom (the profile's lowest point), where a main
//     cornice's consoles carry it (Fig. 5.22).
//   * The depth out of the wall is the profile's reach (its largest x): the console carries the
//     whole overhang. A profile that never leaves the wall gives consoles as deep as they are wide.
#pragma once

#include <vector>

#include "core/vecmath.h"
#include "facade/profile.h"
#include "facade/profile_sweep.h"

namespace veduta {

// The most consoles one run may get.
inline constexpr size_t kConsoleLimit = 100000;

// The transforms of `console` along `path` under the profile traced into `outline`, already
// scaled by `scale` (metres per profile unit: heightScale). InputError at the console when the
// run would take more than kConsoleLimit of them.
std::vector<Transform> placeConsoles(const SweepPath &path, const Console &console, const ProfileOutline &outline,
                                     double scale);

}  // namespace veduta
