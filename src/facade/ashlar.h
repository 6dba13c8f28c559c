// Ashlar masonry (Quadersteinmauerwerk, digest-001 §2.5, Def 5.8, L1050–1072): rectangular stones of
// random size between a minimum and a maximum, laid in courses over one wall face with openings.
// Stones are fitted into the free parts of the wall first; what is left is filled with stones that
// may overlap the openings and are cut to the wall, cut stones split into convex pieces, and pieces
// too small to be cut by a mason dropped (Fig. 5.11).
//
// Choices where the thesis is open:
// * Courses ([GAP]): "in one course the height stays the same, the width varies randomly" (L1029,
//   Fig. 5.12a). Each course draws its height once, lerp(min h, max h, u); each stone draws one value
//   v for its length and depth, lerp(min, max, v) (L1068: "linear interpolation from a random
//   value"). Courses run from the wall's bottom up, each a mortar joint above the last.
// * Fitting: a course's strip is split into runs at the exact ends of its free spans (where the whole
//   strip height is free, WallMask::freeSpans). In a run, stones are laid from the left with a joint
//   after each; a drawn length is shortened where it would leave less than the minimum for the next
//   stone, and the last stone takes what is left when that lies within [min, max], so free runs end
//   flush at the openings' joints. A rest narrower than the minimum, and every stone in a run that
//   is not wholly free, is a cut stone: clipped exactly to the wall minus its grown openings.
// * The runs that are not wholly free are inset by a mortar joint where they meet a free run, so
//   that a cut stone never touches a whole one.
// * "A certain minimum size" (L1072) is a narrowest width (calliper width) of half the smaller
//   minimum dimension, min(min l, min h) / 2: narrower slivers read as mortar, as in Fig. 5.11(b).
// * Cut stones are split into the fewest convex pieces (CGAL's optimal convex partition), the
//   thesis's three pieces in Fig. 5.11; a cut piece that touches itself at a corner (two grown
//   openings meeting there) into triangles (facade/convex_pieces.h).
#pragma once

#include <string>
#include <string_view>

#include "core/error.h"
#include "facade/brick_bond.h"
#include "facade/masonry.h"

namespace veduta {

struct AshlarMasonry {
    StoneSize minSize, maxSize;  // description units
    ColourRange colour;
    double mortarThickness = 0;  // units
    Vec3f mortarColour;          // 0..255
    FileLoc loc;                 // of the AshlarMasonry block
};

// A cut piece narrower than this fraction of min(min length, min height) is dropped.
inline constexpr double kAshlarMinPieceFraction = 0.5;

// Reads `AshlarMasonry { min l,h,t; max l,h,t; r,g,b; r,g,b; mortar; r,g,b; }` (Def 5.8), the text's
// only block. Throws InputError "file:line:col: …" for a syntax error, another block, a missing item,
// a size that is not positive, a size or mortar above kMasonryLengthLimit, a minimum above its
// maximum or a colour outside 0..255.
AshlarMasonry parseAshlarMasonry(std::string_view text, const std::string &file);

// Throws what layAshlar would before it lays a stone: an InputError at the AshlarMasonry block when
// the wall could take more than kBrickLimit stones or the scaled sizes do not suit the wall
// (checkScaledSizes). A wall checked can be laid later without an error to report.
void checkAshlar(const AshlarMasonry &ashlar, const WallFace &wall, double metresPerUnit);

// The stones of `ashlar` laid on `wall` (see above): whole stones axis-parallel rectangles within
// [min, max]; cut stones convex and no narrower than the minimum piece width. Checks first
// (checkAshlar).
Masonry layAshlar(const AshlarMasonry &ashlar, const WallFace &wall, const MasonryPlacement &placement);

}  // namespace veduta
