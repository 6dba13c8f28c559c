// Friezes: textured cornices (digest-001 §2.6, Def 5.11, L1179–1201). Each profile command may
// name a start, a mid and an end texture of the pool; along one edge of the run its band (the
// strip the command sweeps) is cut into a start piece, whole mid tiles, and an end piece, and each
// piece shows exactly its texture rectangle. This lays those pieces out along the strip; the
// sweep (profile_sweep.h) builds them.
//
// Choices where the thesis is open:
//   * A piece keeps its texture's aspect ratio at the strip's height: width = strip height ×
//     (rectangle width / rectangle height) × the image's aspect (pixels wide per pixel high; the
//     pool gives only fractions of the image).
//   * The mid texture fills the rest with the whole number of tiles that comes closest to its
//     aspect ratio (L1186: "so gut wie möglich"), at least one, all of one width, each starting
//     exactly where the one before ends (so a horizontally tileable texture shows no seam).
//   * A negative index leaves that part untextured (L1183). We read it as "no such piece": without
//     a start or end texture there is no end piece (its length goes to the middle), and without a
//     mid texture the middle is one untextured piece.
//   * A strip too short for both end pieces gets only those, shrunk in proportion to fill it.
#pragma once

#include <array>
#include <vector>

#include "facade/profile.h"

namespace veduta {

enum class FriezePart { Start, Mid, End };

struct FriezePiece {
    FriezePart part = FriezePart::Mid;
    double from = 0, to = 0;  // metres along the strip
    int texture = -1;         // index into the pool; negative = untextured
};

// The most mid tiles one strip may get.
inline constexpr int kFriezeTileLimit = 100000;

// The pieces of a strip `length` metres long (≥ 0) and `stripHeight` metres high (> 0) with the
// start, mid and end textures `textures` of `pool` (indices checked by parseCorniceDescription),
// in order, covering [0, length] without gap or overlap. A strip of length 0 is one mid piece.
// InputError at the mid texture when the strip would need more than kFriezeTileLimit tiles.
std::vector<FriezePiece> layFrieze(double length, double stripHeight, const std::array<int, 3> &textures,
                                   const std::vector<TextureRegion> &pool, double imageAspect);

}  // namespace veduta
