// Lot subdivision of city blocks: a block polygon is cut into building footprints that each face
// a street. Bilke's two algorithms (Bilke 2009, §2.1.3, thesis L362–406) and CityEngine's two
// (the OBB split and Vanegas et al. 2012's straight-skeleton strips); docs/lots.md describes
// them and the choices where their sources leave gaps.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "city/footprint.h"
#include "core/error.h"
#include "core/vecmath.h"

namespace veduta {

class SettingsStack;

// The setting LotSubdivision: which algorithm cuts a block.
enum class LotSubdivision {
    Perimeter,  // "perimeter": perimeterLots, recursiveLots where that gives none
    Recursive,  // "recursive"
    Obb,        // "obb"
    Skeleton,   // "skeleton"
    Schrader,   // "schrader"
};

// Bilke's BuildingSettings for lots, in metres, square metres and degrees. The thesis gives
// no defaults; these suit Gründerzeit blocks (frontages of 10–22 m, wings 12 m deep).
struct LotSettings {
    LotSubdivision algorithm = LotSubdivision::Perimeter;
    float minBuildingLength = 10, maxBuildingLength = 22;  // frontage along the street
    float minBuildingDepth = 12;                           // perimeter ring's inset; Schrader's M1
    float minBuildingInnerLength = 4;                      // a lot's side facing the courtyard
    float maxLotArea = 600, minLotArea = 40;               // recursive subdivision
    float minLotAngleDegrees = 30;
    float housingDensity = 1;  // probability a lot is kept
    // Goitowski's margins (thesis L3560–3561), Schrader lots only: every lot stays roadMargin
    // inside the block, and neighbouring lots are buildingMargin apart.
    float roadMargin = 0.6f, buildingMargin = 0.6f;
};

// Reads LotSubdivision, MinBuildingLength, MaxBuildingLength, MinBuildingDepth,
// MinBuildingInnerLength, MaxLotArea, MinLotArea, MinLotAngle, HousingDensity, RoadMargin and
// BuildingMargin; the defaults above where one is not set. InputError at the setting when a
// value is out of its range (see checkLotSettings) or LotSubdivision names no algorithm.
LotSettings lotSettingsFrom(const SettingsStack &settings);

// Throws a LotError (InputError at `loc` when given) unless 0 < MinBuildingLength ≤
// MaxBuildingLength, MinBuildingDepth, MaxLotArea > 0, MinBuildingInnerLength, MinLotArea ≥ 0,
// 0 ≤ MinLotAngle < 180, 0 ≤ HousingDensity ≤ 1, and RoadMargin and BuildingMargin are finite
// and ≥ 0.
void checkLotSettings(const LotSettings &settings, const std::optional<FileLoc> &loc = std::nullopt);

// A city block: a simple counter-clockwise polygon (edge i from points[i] to points[i + 1]),
// one street flag per edge, at ground height `base`. Blocks from user input go through
// normaliseFootprint first, which turns clockwise ones round.
struct Block {
    std::vector<Vec2f> points;
    std::vector<bool> streetEdges;
    float base = 0;
};

// What a subdivision throws when a block is not a simple counter-clockwise polygon with one street
// flag per edge, when settings are out of range, or at the limits below (an InputError instead
// when the caller gives the block's place in its file).
class LotError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// The limits: a block cut into more lots, or recursion deeper, is refused.
inline constexpr size_t kMaxLotsPerBlock = 10000;
inline constexpr int kMaxLotRecursion = 32;

// Perimeter development ("Blockrandbebauung", the thesis' subdivideLotRectangular): the ring
// between the block and its inset by MinBuildingDepth, along the street edges, cut
// perpendicular to the street at frontages drawn from [MinBuildingLength, MaxBuildingLength];
// lots meeting at a corner of two street edges are one corner lot. The inset (the courtyard)
// stays empty. No lots when the block has no street edge or cannot be inset.
std::vector<Footprint> perimeterLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                     const std::optional<FileLoc> &loc = std::nullopt);

// Recursive subdivision (the thesis' subdivideLot-Mueller, after Müller 2001): pieces larger
// than MaxLotArea are split perpendicular to one of their two longest edges near its middle;
// pieces without a street edge are dropped and not split further.
std::vector<Footprint> recursiveLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                     const std::optional<FileLoc> &loc = std::nullopt);

// CityEngine's recursive OBB subdivision (Vanegas et al. 2012): pieces larger than MaxLotArea
// are split by a line across the longer axis of their minimum-area bounding rectangle, near its
// middle; where that leaves a part without a street edge the split across the shorter axis is
// tried instead, and parts that still have none are dropped.
std::vector<Footprint> obbLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                               const std::optional<FileLoc> &loc = std::nullopt);

// Straight-skeleton subdivision (Vanegas et al. 2012): the faces of the block's interior straight
// skeleton become one strip per street edge, corner regions go to the longer of two meeting
// streets, the faces of other edges join a neighbouring strip, and each strip is cut
// perpendicular to its street at frontages drawn from [MinBuildingLength, MaxBuildingLength].
std::vector<Footprint> skeletonLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                    const std::optional<FileLoc> &loc = std::nullopt);

// Goitowski's simplified Schrader 2007 subdivision (digest-002 §3.2): ⌊perimeter / D⌋ markers,
// D the mean of MinBuildingLength and MaxBuildingLength, each given to the edge whose pieces are
// then longest; a ray inwards, perpendicular to its edge, from each marker; each lot runs along
// the outline between two neighbouring markers and back to the rays' frontmost crossings with
// other rays. Lots that front no street are dropped; the rest are kept RoadMargin inside the
// block and BuildingMargin apart. The seed only keys the HousingDensity filter.
std::vector<Footprint> schraderLots(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                    const std::optional<FileLoc> &loc = std::nullopt);

// The lots of the algorithm settings.algorithm names; for Perimeter, recursiveLots where
// perimeterLots gives none (a piece too small for a ring of houses round a courtyard).
std::vector<Footprint> subdivideBlock(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                      const std::optional<FileLoc> &loc = std::nullopt);

// The algorithms' final filters (thesis L370–374): the lots with area > MinLotArea and every
// interior angle > MinLotAngle, each of those kept with probability HousingDensity (a pure
// function of seed, blockId and the lot's index in `lots`).
std::vector<Footprint> filterLots(std::vector<Footprint> lots, const LotSettings &settings, uint32_t seed,
                                  uint32_t blockId);

// Shared by the algorithms.
namespace lots {
[[noreturn]] void fail(const std::optional<FileLoc> &loc, const std::string &message);
// Checks the block's shape and flags (LotError or InputError).
void checkBlock(const Block &block, const std::optional<FileLoc> &loc);
// perimeterLots before the filters.
std::vector<Footprint> perimeterPieces(const Block &block, const LotSettings &settings, uint32_t seed, uint32_t blockId,
                                       const std::optional<FileLoc> &loc);
// Checks the block and the settings, and says whether the block has a street edge, without
// which the algorithms that build along streets cut no lots.
bool checkedAndOnAStreet(const Block &block, const LotSettings &settings, const std::optional<FileLoc> &loc);
// A draw from a normal distribution centred in [lo, hi] with σ = (hi − lo) / 6, clamped to
// the range (the thesis says "normally distributed in the range" and gives no σ); a pure
// function of the hash `key`.
float normalBetween(float lo, float hi, uint32_t key);
}  // namespace lots

}  // namespace veduta
