// Cyclopean masonry (Zyklopenmauerwerk, digest-001 §2.5, L1084–1105): large irregular convex
// stones with joints of varying width and no bed joints, made as the Voronoi cells of relaxed seed
// points clipped to the wall minus its openings.
//
// The steps: the stone count of hexagonal packing less 20 % (L1091); seeds spread over a grid of
// cells lying mostly in the wall (L1094); a pair of fixed seeds at every reflex corner of the wall
// region (Fig. 5.15, L1098–1103), so that no clipped cell turns concave there; Lloyd relaxation of
// the other seeds (facade/lloyd_relaxation.h); each cell shrunk by half a joint into a stone.
//
// Where the thesis is open, chosen here:
// * n_v is floored (the thesis prints no brackets; only whole courses exist), and the 20 % cut is
//   rounded to the nearest stone. A wall with openings takes the count of its bounding a × b
//   rectangle scaled by the share of it that is wall.
// * `Steine` given instead of `Abstand`: the mean radius is the one whose hexagonal cells, 20 %
//   fewer, fill the wall: r = √(0.8·A / (2√3·n)).
// * The cell grid has square cells holding 4 seeds each on average ("gleich viele Punkte": the
//   same number in every cell, the number of the wall's count over the cells taken); a cell is
//   taken when at least half of it is wall, or, on a wall too narrow for any such cell, when any
//   of it is.
// * The corner fix is applied once, to the seeds before relaxation, not between two relaxations:
//   the result is the same kind of layout at half the work, and `Lloyd` keeps its meaning as the
//   number of steps. A corner's PD is 2r, shrunk so that no two corners' PD circles overlap (they
//   touch at most, L1103) and so that PD stays within the corner's distance to the rest of the
//   boundary (its fixed seeds then lie inside the wall; the thesis does not say).
// * Lloyd stops when no seed moves more than r/1000 (the threshold is not given).
// * Joints: every edge of a cell is moved inwards by half the joint times a factor drawn in
//   [0.5, 1.5] per stone and edge, so a joint between two stones varies between 0.5 and 1.5 joints
//   and is one joint wide on average ("variable Dicke", L1084); at the wall's edges and openings
//   half a joint is left, the other half belonging to the corner or the casing beside it.
// * A stone's colour is start + t·(end − start) with one t drawn per stone, so that stones keep
//   the hue between the two colours.
// * A clipped cell that is still concave or holds a hole (possible only where a free seed wanders
//   close to a corner, or an opening is smaller than a stone) is split into convex pieces, as the
//   ashlar stones are (Fig. 5.11, facade/convex_pieces.h).
//
// The description text, one block in the syntax of the other masonry languages (description_text.h),
// its items in the order of AshlarMasonry's (Def 5.8) after Def A.16's attributes:
//
//   CyclopeanMasonry { spacing, 0.8; 30; 120,110,100; 160,150,135; 0.03; 150,150,150; 0.02; }
//
// `spacing, metres` (Abstand) or `stones, count` (Steine); Lloyd steps; the stones' start and end
// colours; the joint (metres); the mortar colour; the stones' depth out of the mortar (metres).
// Unlike bricks and ashlar the sizes are metres, not units: a cyclopean wall has no stone size to
// scale. Colours are 8-bit display (sRGB) values 0..255, decoded to linear as brick colours are.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/lloyd_relaxation.h"
#include "facade/masonry.h"

namespace veduta {

// The description of a cyclopean wall (`Zyklopenmauerwerk {Steine, Abstand, Lloyd}`, Def A.16,
// plus the colours and joint every masonry has). Exactly one of `stones` and `spacing` is set.
struct CyclopeanMasonry {
    int stones = 0;      // `Steine`: stones on the wall
    double spacing = 0;  // `Abstand`: mean distance between stone centres, metres (2r)
    int lloyd = 0;       // `Lloyd`: the most relaxation steps
    Vec3f startColour;   // the stones' colours lie between these, linear RGB in [0, 1]
    Vec3f endColour;
    double joint = 0;  // mean joint width, metres
    Vec3f mortarColour;
    double depth = 0;  // how far the stones stand out of the mortar, metres
    FileLoc loc;       // where the description was written, for its errors
};

// The limits a description is held to: more is refused with an InputError at its place.
inline constexpr int64_t kMaxCyclopeanStones = 20000;  // per wall
inline constexpr int kMaxLloydSteps = 1000;

// The stone count of an a × b wall for mean stone radius r (L1091), each step kept for checking.
struct CyclopeanStoneCount {
    int64_t firstCourse = 0;   // n1 = ⌊a / 2r⌋
    int64_t secondCourse = 0;  // n2 = ⌊(a − r) / 2r⌋
    int64_t courses = 0;       // n_v = ⌊(b − 2r) / (√3·r) + 1⌋
    int64_t packed = 0;        // n = ⌈n_v / 2⌉·n1 + ⌊n_v / 2⌋·n2
    int64_t stones = 0;        // n less 20 %, rounded
};
// Reads the text above, the text's only block. Throws InputError "file:line:col: …" for a syntax
// error, another block, a missing item, a spacing that is not positive, a count or Lloyd steps
// that are not whole or beyond kMaxCyclopeanStones / kMaxLloydSteps, a length beyond
// kMasonryLengthLimit or a colour outside 0..255.
CyclopeanMasonry parseCyclopeanMasonry(std::string_view text, const std::string &file);

// Needs width / radius and height / radius below 10^15 (whole numbers in double).
CyclopeanStoneCount cyclopeanStoneCount(double width, double height, double radius);

// The two fixed seeds at one reflex corner of the wall region (Fig. 5.15): each `distance` / 2
// from the corner, `distance` (PD) apart, on the line through the corner perpendicular to the
// corner's bisector, so that their shared Voronoi edge runs along the bisector through the corner.
struct CornerSeeds {
    Vec2d corner;
    double distance = 0;  // PD
    Vec2d first, second;
};

// The corner seeds for every reflex corner of `region` (the wall's concave corners and the
// openings' convex ones), for PD = `pointDistance` before shrinking.
std::vector<CornerSeeds> cornerSeeds(const WallRegion &region, double pointDistance);

// The seeds before relaxation, and the layout after it.
struct CyclopeanLayout {
    double radius = 0;        // r, the mean stone radius
    int64_t targetCount = 0;  // the stones the count asks for
    std::vector<CornerSeeds> corners;
    LloydResult relaxed;  // seeds (the corners' first, two each), cells, shift record
};

// Spreads the seeds, fixes the corners and relaxes. Throws InputError at `description.loc` for a
// description that is not usable or asks for more than the limits.
CyclopeanLayout layOutCyclopean(const WallRegion &region, const CyclopeanMasonry &description, uint32_t seed,
                                uint32_t wallId);

// Throws what cyclopeanMasonry would before it lays a stone (layOutCyclopean's InputError). A wall
// checked can be laid later without an error to report.
void checkCyclopean(const WallFace &wall, const CyclopeanMasonry &description);

// The masonry of one wall face: its stones, seeded from `seed` and the wall's stable `wallId`.
Masonry cyclopeanMasonry(const WallFace &wall, const CyclopeanMasonry &description, uint32_t seed, uint32_t wallId);

}  // namespace veduta
