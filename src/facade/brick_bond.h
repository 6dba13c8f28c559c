// Brick bonds (Mauerziegelverbände, digest-001 §2.5, Defs 5.5–5.7, L1034–1043): the three-level
// description language — bricks, a pattern of courses, the masonry with its mortar — and the
// layout of such a bond over one wall face with openings (L1050–1054). Also the colour ranges and
// the layout parameters that ashlar (facade/ashlar.h) shares with bricks.
//
// Reading of the thesis, and choices where it is open:
// * A description has `Brick`-shaped blocks under any name (`Brick1 { … }`), pattern blocks under
//   any name, and one block named `BrickMasonry` whose first item quotes the pattern's name. The
//   pattern quotes brick names; a bare number is a gap (luecke). Every block must be the masonry,
//   its pattern or one of the pattern's bricks, so that a misspelt name is reported, not ignored.
// * Units are the description's own (L1043: "arbitrary"); the layout scales them by
//   `metresPerUnit`. Colours are 8-bit display (sRGB) values 0..255, decoded to linear RGB.
// * One brick's colour is start + t · (end − start) with one uniform t per brick (a shade between
//   the two colours, as ashlar draws its size "with one random value"), not three independent
//   channels, which would mix hues that lie in neither colour.
// * `versatz` accumulates down the list: the first course's offset is its own, each next one's is
//   the previous course's plus its `versatz` (Fig. 5.7: −1, 0, 1 give courses at −1, −1, 0). Each
//   repetition of the list starts afresh, so the bond repeats exactly (L1037: a higher course repeats
//   a lower one exactly); a rising bond lists one period of courses.
// * The courses are listed top to bottom and laid in reverse (L1037): the last listed course is the
//   wall's bottom course, and the list repeats upward until the wall is full.
// * Along a course the bricks and gaps repeat with one mortar joint after each, a gap standing for a
//   brick of its length (Fig. 5.7 puts the gap 2.0 under Brick2, also 2.0 long). The offset shifts
//   the course's start from the wall's left edge.
// * A course is as high as its lowest brick. A taller brick ("armiert", L1029) hangs down from its
//   course's top into the gaps of the courses listed after it, which lie below it (Fig. 5.7: Brick2
//   of the first course lies exactly over the gap of the second, while the third has a brick
//   there). Its height is snapped to the courses it spans with their joints (L1029: "composed of the
//   heights of the courses it spans, with mortar"), so Brick2's 1.0 becomes 0.5 + 0.05 + 0.5 = 1.05:
//   the thesis's 1.0 would leave a joint twice as thick under it (digest §10, L1043). Parsing
//   checks that a spanned course has a gap under the whole brick (same course length required).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/description_text.h"
#include "facade/masonry.h"

namespace veduta {

// A colour drawn between two 8-bit display colours.
struct ColourRange {
    Vec3f start, end;  // 0..255 per channel, as written

    // The colour at `t` in [0, 1] of the way from start to end, as linear RGB in [0, 1].
    Vec3f at(float t) const;
};

// The item as a colour `r, g, b`: three whole numbers 0..255 (InputError with the place otherwise).
Vec3f readColour(const DescriptionItem &item, std::string_view what);

// The largest length, height, depth, gap, offset or mortar thickness a description may give, in its
// units: beyond any masonry in any unit one is written in, and small enough that a course's sums of
// kBondUnitLimit lengths, scaled to metres, stay finite.
inline constexpr double kMasonryLengthLimit = 1e4;

struct StoneSize {
    double length = 0, height = 0, depth = 0;
};
// The item as a size `laenge, hoehe, tiefe` (Def 5.5 `groesse`): length and height positive, depth
// (the protrusion over the mortar) not negative, none above kMasonryLengthLimit.
StoneSize readStoneSize(const DescriptionItem &item, std::string_view what);

// The item as a mortar thickness: one number, not negative, not above kMasonryLengthLimit.
double readMortarThickness(const DescriptionItem &item);

// What places a description on one wall: its scale and the identity its random choices hash.
struct MasonryPlacement {
    double metresPerUnit = 1;
    uint32_t seed = 0;
    uint32_t wallId = 0;  // the stable identity of the wall face
};

// Refuses, with an InputError at `loc`, sizes scaled to metres that the layout cannot work with on
// `wall`: `largest` (the largest size, gap, offset or mortar) not finite or above
// kScaledSizeLimit times the wall's extent, where its sums would overflow; `least` (the smallest
// stone length or height) below kScaledSizeResolution times the wall's distance from the origin
// plus its extent, where a course or a stone would no longer move the walk along.
inline constexpr double kScaledSizeLimit = 1e6;
inline constexpr double kScaledSizeResolution = 1e-9;
void checkScaledSizes(const WallFace &wall, double least, double largest, const FileLoc &loc);

struct BrickKind {
    std::string name;
    StoneSize size;  // description units
    ColourRange colour;
    FileLoc loc;
};

// One place along a course: a brick (an index into BrickBond::bricks) or a gap.
struct BondUnit {
    int brick = -1;     // -1 for a gap
    double length = 0;  // the brick's or gap's length, units
    int spans = 1;      // how many courses a brick covers, downward from its own (1 for a gap)
    double height = 0;  // a brick's height snapped to the courses it spans, units
    FileLoc loc;
};

struct BondCourse {
    double offset = 0;  // from the wall's left edge, after accumulating `versatz` (see above)
    double height = 0;  // of its lowest brick, units
    double length = 0;  // of one repetition: its units with a joint after each, units
    std::vector<BondUnit> units;
    FileLoc loc;
};

struct BrickBond {
    std::vector<BrickKind> bricks;
    std::vector<BondCourse> courses;  // as listed: top to bottom
    double mortarThickness = 0;       // units
    Vec3f mortarColour;               // 0..255
    FileLoc loc;                      // of the BrickMasonry block
};

// The most bricks one pattern course may list, and the most courses a pattern may list.
inline constexpr size_t kBondUnitLimit = 1000;
inline constexpr size_t kBondCourseLimit = 1000;
// The most bricks one wall may receive; a finer bond is refused (the scale is likely wrong).
inline constexpr size_t kBrickLimit = size_t(1) << 20;

// Reads a brick-bond description (Defs 5.5–5.7). Throws InputError "file:line:col: …" for a
// syntax error, a missing or unused block, an unknown name, a size that is not positive, a size,
// gap, offset or mortar beyond kMasonryLengthLimit, a colour outside 0..255 or not whole, a course without a brick, or
// a tall brick with no gap under it.
BrickBond parseBrickBond(std::string_view text, const std::string &file);

// Throws what layBrickBond would before it lays a brick: an InputError at the BrickMasonry block
// when the wall could take more than kBrickLimit bricks or the scaled sizes do not suit the wall
// (checkScaledSizes). A wall checked can be laid later without an error to report.
void checkBrickBond(const BrickBond &bond, const WallFace &wall, double metresPerUnit);

// The bond laid on `wall` (L1050–1054): bricks wholly in the free region kept, those wholly out
// dropped, the rest cut exactly to the wall minus its openings grown by the mortar; a cut brick
// may be non-convex or fall into pieces, each a Stone; pieces of a billionth of their brick's area
// (rounding slivers where a brick meets an opening's joint) are dropped. Checks first
// (checkBrickBond).
Masonry layBrickBond(const BrickBond &bond, const WallFace &wall, const MasonryPlacement &placement);

}  // namespace veduta
