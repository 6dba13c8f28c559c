// Schrader's urban geography (digest-003 §4, thesis ch. 6): the land uses and the locality each
// object of the hierarchy hands down to its children, and what they decide below it: lot and
// building areas, Bauweise, placement, storeys and their uses, roofs, and the plan parameters of
// every level. The numbers are the thesis's tables, read from rules/slg/urban-geography.xml into
// UrbanGeography (urban_geography_file.h); the functions here are its formulas. Every rand() is
// a draw of PlanRandom on the stream SlgParameters, so that an object's parameters depend only
// on the seed and its identity (docs/urban-geography.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "slg/building_placement.h"
#include "slg/plan_level.h"
#include "slg/plan_parameters.h"
#include "slg/plan_random.h"
#include "slg/storey_parameters.h"

namespace veduta {

// Table 1.
enum class CitySize : uint8_t { Landstadt, Kleinstadt, Mittelstadt, Grossstadt };
inline constexpr int kCitySizes = 4;

// Boustedt's regions: Stadtkern, Stadtmantel, Stadtrand.
enum class Locality : uint8_t { Kern, Mantel, Rand };
inline constexpr int kLocalities = 3;

enum class LandUse : uint8_t { Industrie, Wohnen, Buero, Einzelhandel, Gastronomie, Freiflaeche };
inline constexpr int kLandUses = 6;
// Weights, not shares: only their ratios to the sum mean something (eq 42).
using LandUseWeights = std::array<double, kLandUses>;

// Eq 43 (FN_general); Unbebaut is eq 48's open land.
enum class DominantUse : uint8_t { Industriegebiet, Gewerbegebiet, Wohngebiet, Mischgebiet, Unbebaut };
inline constexpr int kDominantUses = 5;

enum class RoofOrientation : uint8_t { Giebelstaendig, Traufstaendig };
inline constexpr int kRoofOrientations = 2;
enum class RoofKind : uint8_t { Flat, Gable, Tent };
enum class EntranceSide : uint8_t { Street, Rear };

// Where the gap between the faces starts: the street, computed (eq 58 for a building), or no gap.
enum class GapStart : uint8_t { None, StreetSide, Computed };

struct Range {
    double low = 0, high = 0;
};

// base + r(0, extra), r an integer drawn inclusively (eq 59–61).
struct StoreyRange {
    int base = 0, extra = 0;
};

struct BaunvoZone {
    std::string name;
    double grz = 0, gfz = 0;
};

// What eq 45 and 46 give a lot of one dominant use and locality, and the BauNVO zone its
// density is compared with (none for open land).
struct LotTable {
    double lotArea = 0, buildingArea = 0;
    std::optional<size_t> zone;  // into UrbanGeography::zones
};

struct LevelPlan {
    PlanParameters parameters;  // a block's average area is eq 45's, not the table's
    GapStart gapStart = GapStart::None;
};

// The land uses and locality of an object that has no parent (Tables 5, 7, 10, 14).
struct Geography {
    LandUseWeights weights{};
    std::optional<Locality> locality;  // a city's stays undefined
};

struct RoofRanges {
    Range height, gableOverhang, eavesOverhang;
    double thickness = 0;
};

template <typename T>
using ByUseAndLocality = std::array<std::array<T, kLocalities>, kDominantUses>;
using LandUseFactors = std::array<Range, kLandUses>;

// Every table of digest-003 §4, as rules/slg/urban-geography.xml gives them.
struct UrbanGeography {
    std::array<double, kCitySizes> inhabitantsAbove{};                          // Table 1: a size needs more than this
    std::vector<BaunvoZone> zones;                                              // Table 2
    std::array<LandUseFactors, kLocalities> childFactors{};                     // eq 39–41
    LandUseFactors lotFactors{};                                                // eq 47
    std::array<LandUseWeights, kDominantUses> blockMasks{}, lotMasks{};         // eq 44, 48
    ByUseAndLocality<LotTable> lots{};                                          // eq 45–46
    std::array<ByUseAndLocality<StoreyRange>, kCitySizes> storeyCounts{};       // eq 59–61
    int einzelhandelStoreysAtMost = 0, gastronomieStoreysAtMost = 0;            // eq 62
    std::array<LevelPlan, kPlanLevels> plans{};                                 // Tables 4, 6, 9, 13, 16
    Geography cityDefaults, districtDefaults, blockDefaults, buildingDefaults;  // Tables 5, 7, 10, 14
    Range sidewalkWidth;                                                        // Table 11
    std::array<Range, kRoofOrientations> sideRatios{};                          // eq 51
    double wallThickness = 0, stairwellArea = 0;                                // Table 12
    RoofRanges roof;                                                            // eq 64
    std::vector<StoreyParameters> storeys;                                      // Table 15
};

// The parameters' draws: seed and the object's stable identity (a block's, a lot's, a
// building's) on the stream of the cascade.
inline PlanRandom parameterRandom(uint32_t seed, uint32_t identity) {
    return PlanRandom(seed, identity, RandomStream::SlgParameters);
}

// Table 1; fewer inhabitants than any size asks for make the smallest.
CitySize citySize(const UrbanGeography &geography, double inhabitants);

// Eq 38: d is the distance of the child's centre from the city's local centre, dMax the
// farthest corner of the city from it.
Locality locality(double d, double dMax);

// Eq 39–41: each weight of the parent times rand(a, b) of the child's locality.
LandUseWeights childWeights(const UrbanGeography &geography, const LandUseWeights &parent, Locality locality,
                            const PlanRandom &random);

// Eq 42: the weights as percent of their sum; all zero when the sum is.
LandUseWeights shares(const LandUseWeights &weights);

// Eq 43: a share of at least half decides, Büro and Einzelhandel together as Gewerbe; on an
// exact half of Wohnen against Büro and Einzelhandel, Wohnen.
DominantUse dominantUse(const LandUseWeights &weights);

// Eq 44: a block keeps the uses its dominant use allows.
LandUseWeights blockWeights(const UrbanGeography &geography, const LandUseWeights &drawn);

// Eq 47–48: a lot's weights, each the block's times rand(0, 1), then kept as the block's
// dominant use allows.
LandUseWeights lotWeights(const UrbanGeography &geography, const LandUseWeights &block, const PlanRandom &random);

// Eq 45 and 46.
double averageLotArea(const UrbanGeography &geography, DominantUse use, Locality locality);
double averageBuildingArea(const UrbanGeography &geography, DominantUse use, Locality locality);

// Eq 57.
Bauweise bauweise(DominantUse use, Locality locality);

// Eq 49–51.
Alignment alignment(Bauweise bauweise, const PlanRandom &random);
RoofOrientation roofOrientation(Bauweise bauweise, const PlanRandom &random);
double sideRatio(const UrbanGeography &geography, RoofOrientation orientation, const PlanRandom &random);

// Table 11.
double sidewalkWidth(const UrbanGeography &geography, const PlanRandom &random);

// Eq 59–61; a building outside any city stands in a Mittelstadt (footnote 78).
int storeyCount(const UrbanGeography &geography, std::optional<CitySize> city, DominantUse use, Locality locality,
                const PlanRandom &random);

// Eq 62, step by step as the thesis orders it, indexed by StoreyUse.
using StoreysPerUse = std::array<int, kStoreyUses>;
StoreysPerUse storeysPerUse(const UrbanGeography &geography, int storeys, const LandUseWeights &weights);

// Eq 62 step 3: one use per storey, from the ground floor up.
std::vector<StoreyUse> stackStoreys(const StoreysPerUse &counts);

// Eq 58: shops and restaurants have their own doors to the street, so the house's is at the back.
EntranceSide entranceSide(StoreyUse groundFloor);

// Eq 63, with a gable roof on a footprint of other than four corners made a tent roof.
RoofKind roofKind(const LandUseWeights &weights, int footprintCorners, const PlanRandom &random);

struct RoofDimensions {
    double height = 0, thickness = 0, gableOverhang = 0, eavesOverhang = 0;
};
// Eq 64.
RoofDimensions roofDimensions(const UrbanGeography &geography, const PlanRandom &random);

// Tables 4, 6, 13, 16. A block's plan needs its lots' area: blockPlanParameters.
PlanParameters planParameters(const UrbanGeography &geography, PlanLevel level);
// Table 9 with eq 45's average lot area.
PlanParameters blockPlanParameters(const UrbanGeography &geography, DominantUse use, Locality locality);

// The predefined storey set for a use on this floor (0 the ground floor), if the file has one.
std::optional<StoreyParameters> storeyParameters(const UrbanGeography &geography, StoreyUse use, int floor);

// GRZ and GFZ (eq 1) of a built lot beside the BauNVO caps of its zone (Table 2). The thesis
// takes them as guidance only, so this reports and does not judge.
struct DensityReport {
    double grz = 0, gfz = 0;
    std::optional<BaunvoZone> zone;
};
DensityReport densityReport(const UrbanGeography &geography, DominantUse use, Locality locality, double lotArea,
                            double footprintArea, std::span<const double> storeyAreas);

}  // namespace veduta
