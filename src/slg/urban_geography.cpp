#include "slg/urban_geography.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/check.h"

namespace veduta {

namespace {

// What each draw is for: a purpose of PlanRandom. The values go into the hashes, so renumbering
// one changes every plan made with it.
enum class Draw : uint32_t {
    ChildWeight = 1,  // index: the land use
    LotWeight,        // index: the land use
    Alignment,
    RoofOrientation,
    SideRatio,
    SidewalkWidth,
    StoreyCount,
    RoofKind,
    RoofHeight,
    GableOverhang,
    EavesOverhang,
};

double uniform(const PlanRandom &random, Range range, Draw what, uint32_t index = 0) {
    return random.uniform(range.low, range.high, uint32_t(what), index);
}

// The thesis's integer rand(0, top), both ends included.
int integer(const PlanRandom &random, int top, Draw what) {
    return std::min(int(random.uniform(0, top + 1, uint32_t(what))), top);
}

double weight(const LandUseWeights &weights, LandUse use) { return weights[size_t(use)]; }

double total(const LandUseWeights &weights) { return std::accumulate(weights.begin(), weights.end(), 0.0); }

LandUseWeights timesFactors(const LandUseWeights &weights, const LandUseFactors &factors, Draw what,
                            const PlanRandom &random) {
    LandUseWeights result{};
    for (size_t i = 0; i < result.size(); ++i) result[i] = weights[i] * uniform(random, factors[i], what, uint32_t(i));
    return result;
}

LandUseWeights masked(const LandUseWeights &weights, const LandUseWeights &mask) {
    LandUseWeights result{};
    for (size_t i = 0; i < result.size(); ++i) result[i] = weights[i] * mask[i];
    return result;
}

const LotTable &lotTable(const UrbanGeography &geography, DominantUse use, Locality locality) {
    return geography.lots[size_t(use)][size_t(locality)];
}

// ⌊min(n·w/T, cap) + .5⌋ of eq 62; nothing when no weight is left to share.
int roundedShare(int storeys, double w, double t, double cap = std::numeric_limits<double>::infinity()) {
    if (t <= 0) return 0;
    return std::clamp(int(std::floor(std::min(storeys * w / t, cap) + 0.5)), 0, storeys);
}

}  // namespace

CitySize citySize(const UrbanGeography &geography, double inhabitants) {
    CitySize size = CitySize::Landstadt;
    for (int i = 0; i < kCitySizes; ++i)
        if (inhabitants > geography.inhabitantsAbove[size_t(i)]) size = CitySize(i);
    return size;
}

Locality locality(double d, double dMax) {
    if (d > dMax * 2 / 3) return Locality::Rand;
    if (d < dMax / 3) return Locality::Kern;
    return Locality::Mantel;
}

LandUseWeights childWeights(const UrbanGeography &geography, const LandUseWeights &parent, Locality locality,
                            const PlanRandom &random) {
    return timesFactors(parent, geography.childFactors[size_t(locality)], Draw::ChildWeight, random);
}

LandUseWeights shares(const LandUseWeights &weights) {
    double sum = total(weights);
    LandUseWeights result{};
    if (sum <= 0) return result;
    for (size_t i = 0; i < result.size(); ++i) result[i] = weights[i] / sum * 100;
    return result;
}

DominantUse dominantUse(const LandUseWeights &weights) {
    double sum = total(weights);
    // Nothing to build on is open land, as is land that is mostly Freifläche (eq 43 names no
    // rule for it; eq 48 has the use).
    if (sum <= 0) return DominantUse::Unbebaut;
    auto decides = [&](double share) { return 2 * share >= sum; };
    if (decides(weight(weights, LandUse::Industrie))) return DominantUse::Industriegebiet;
    // Wohnen is asked before Büro and Einzelhandel together, against eq 43's order, so that an
    // exact half of housing makes a Wohngebiet: Table 14's default building (Wohnen 50, Büro 40,
    // EH 10), textured as a dwelling by Table 12, is a house, not an office block.
    if (decides(weight(weights, LandUse::Wohnen))) return DominantUse::Wohngebiet;
    if (decides(weight(weights, LandUse::Buero) + weight(weights, LandUse::Einzelhandel)))
        return DominantUse::Gewerbegebiet;
    if (decides(weight(weights, LandUse::Freiflaeche))) return DominantUse::Unbebaut;
    return DominantUse::Mischgebiet;
}

LandUseWeights blockWeights(const UrbanGeography &geography, const LandUseWeights &drawn) {
    return masked(drawn, geography.blockMasks[size_t(dominantUse(drawn))]);
}

LandUseWeights lotWeights(const UrbanGeography &geography, const LandUseWeights &block, const PlanRandom &random) {
    LandUseWeights drawn = timesFactors(block, geography.lotFactors, Draw::LotWeight, random);
    return masked(drawn, geography.lotMasks[size_t(dominantUse(block))]);
}

double averageLotArea(const UrbanGeography &geography, DominantUse use, Locality locality) {
    return lotTable(geography, use, locality).lotArea;
}

double averageBuildingArea(const UrbanGeography &geography, DominantUse use, Locality locality) {
    return lotTable(geography, use, locality).buildingArea;
}

Bauweise bauweise(DominantUse use, Locality locality) {
    if (locality == Locality::Kern) return Bauweise::Closed;
    if (locality == Locality::Rand) return Bauweise::Open;
    // In the Mantel eq 57 names only the four built uses; open land stands free like industry.
    bool housing = use == DominantUse::Wohngebiet || use == DominantUse::Mischgebiet;
    return housing ? Bauweise::SemiOpen : Bauweise::Open;
}

Alignment alignment(Bauweise bauweise, const PlanRandom &random) {
    if (bauweise != Bauweise::Open) return Alignment::Front;
    return Alignment(integer(random, 2, Draw::Alignment));
}

RoofOrientation roofOrientation(Bauweise bauweise, const PlanRandom &random) {
    if (bauweise != Bauweise::Open) return RoofOrientation::Giebelstaendig;
    return RoofOrientation(integer(random, 1, Draw::RoofOrientation));
}

double sideRatio(const UrbanGeography &geography, RoofOrientation orientation, const PlanRandom &random) {
    return uniform(random, geography.sideRatios[size_t(orientation)], Draw::SideRatio);
}

double sidewalkWidth(const UrbanGeography &geography, const PlanRandom &random) {
    return uniform(random, geography.sidewalkWidth, Draw::SidewalkWidth);
}

int storeyCount(const UrbanGeography &geography, std::optional<CitySize> city, DominantUse use, Locality locality,
                const PlanRandom &random) {
    const StoreyRange &range =
        geography.storeyCounts[size_t(city.value_or(CitySize::Mittelstadt))][size_t(use)][size_t(locality)];
    return range.base + integer(random, range.extra, Draw::StoreyCount);
}

StoreysPerUse storeysPerUse(const UrbanGeography &geography, int storeys, const LandUseWeights &weights) {
    StoreysPerUse counts{};
    auto count = [&](StoreyUse use) -> int & { return counts[size_t(use)]; };
    double t = total(weights);
    double retail = weight(weights, LandUse::Einzelhandel), gastronomy = weight(weights, LandUse::Gastronomie);
    count(StoreyUse::Einzelhandel) = roundedShare(storeys, retail, t, geography.einzelhandelStoreysAtMost);
    count(StoreyUse::Gastronomie) = roundedShare(storeys, gastronomy, t, geography.gastronomieStoreysAtMost);
    t -= retail + gastronomy;
    // A house has shops or restaurants, not both: the larger weight wins, shops on a tie.
    if (retail <= gastronomy) count(StoreyUse::Einzelhandel) = 0;
    else count(StoreyUse::Gastronomie) = 0;
    storeys -= count(StoreyUse::Einzelhandel) + count(StoreyUse::Gastronomie);
    for (auto [storeyUse, landUse] :
         {std::pair{StoreyUse::Industrie, LandUse::Industrie}, std::pair{StoreyUse::Buero, LandUse::Buero}}) {
        double w = weight(weights, landUse);
        count(storeyUse) = roundedShare(storeys, w, t);
        t -= w;
        storeys -= count(storeyUse);
    }
    // Eq 62's last share, ⌊n·W/T + .5⌋, is all that is left whenever no Freifläche weight
    // remains; Wohnen takes the rest in any case so that no storey is left without a use.
    count(StoreyUse::Wohnen) = storeys;
    return counts;
}

std::vector<StoreyUse> stackStoreys(const StoreysPerUse &counts) {
    std::vector<StoreyUse> stack;
    for (int use = 0; use < kStoreyUses; ++use) stack.insert(stack.end(), size_t(counts[size_t(use)]), StoreyUse(use));
    return stack;
}

EntranceSide entranceSide(StoreyUse groundFloor) {
    bool ownDoors = groundFloor == StoreyUse::Einzelhandel || groundFloor == StoreyUse::Gastronomie;
    return ownDoors ? EntranceSide::Rear : EntranceSide::Street;
}

RoofKind roofKind(const LandUseWeights &weights, int footprintCorners, const PlanRandom &random) {
    RoofKind kind = RoofKind::Gable;
    if (weight(weights, LandUse::Industrie) > 0) {
        if (integer(random, 1, Draw::RoofKind) == 0) kind = RoofKind::Flat;
    } else if (weight(weights, LandUse::Buero) > weight(weights, LandUse::Wohnen)) {
        kind = RoofKind::Flat;
    }
    return kind == RoofKind::Gable && footprintCorners != 4 ? RoofKind::Tent : kind;
}

RoofDimensions roofDimensions(const UrbanGeography &geography, const PlanRandom &random) {
    const RoofRanges &roof = geography.roof;
    return {uniform(random, roof.height, Draw::RoofHeight), roof.thickness,
            uniform(random, roof.gableOverhang, Draw::GableOverhang),
            uniform(random, roof.eavesOverhang, Draw::EavesOverhang)};
}

PlanParameters planParameters(const UrbanGeography &geography, PlanLevel level) {
    VEDUTA_CHECK(level != PlanLevel::Block, "a block's plan takes its average area from eq 45: blockPlanParameters");
    return geography.plans[size_t(level)].parameters;
}

PlanParameters blockPlanParameters(const UrbanGeography &geography, DominantUse use, Locality locality) {
    PlanParameters parameters = geography.plans[size_t(PlanLevel::Block)].parameters;
    parameters.averageArea = averageLotArea(geography, use, locality);
    return parameters;
}

std::optional<StoreyParameters> storeyParameters(const UrbanGeography &geography, StoreyUse use, int floor) {
    for (const StoreyParameters &storey : geography.storeys)
        if (storey.use == use && storey.groundFloor == (floor == 0)) return storey;
    return std::nullopt;
}

DensityReport densityReport(const UrbanGeography &geography, DominantUse use, Locality locality, double lotArea,
                            double footprintArea, std::span<const double> storeyAreas) {
    VEDUTA_CHECK(lotArea > 0, "a lot without area has no density");
    DensityReport report;
    report.grz = footprintArea / lotArea;
    report.gfz = std::accumulate(storeyAreas.begin(), storeyAreas.end(), 0.0) / lotArea;
    if (std::optional<size_t> zone = lotTable(geography, use, locality).zone) report.zone = geography.zones[*zone];
    return report;
}

}  // namespace veduta
