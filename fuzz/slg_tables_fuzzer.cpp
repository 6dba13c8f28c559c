// The urban-geography table reader (docs/urban-geography.md) on any text, and the cascade run on
// what it reads for every city size, dominant use and locality: whatever the tables hold, the
// storeys of a building must add up to its count and keep to eq 59–61's range, and every draw
// must stay in its rand(a, b).
#include <cmath>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "slg/urban_geography.h"
#include "slg/urban_geography_file.h"

namespace {

using namespace veduta;

constexpr uint32_t kSeed = 7;

void require(bool holds) {
    if (!holds) __builtin_trap();
}

bool within(double value, Range range) { return value >= range.low && value <= range.high; }

void buildingOfEveryKind(const UrbanGeography &geography, const PlanRandom &random) {
    for (int size = 0; size < kCitySizes; ++size)
        for (int use = 0; use < kDominantUses; ++use)
            for (int place = 0; place < kLocalities; ++place) {
                StoreyRange range = geography.storeyCounts[size_t(size)][size_t(use)][size_t(place)];
                int storeys = storeyCount(geography, CitySize(size), DominantUse(use), Locality(place), random);
                require(storeys >= range.base && storeys <= range.base + range.extra);
                StoreysPerUse counts = storeysPerUse(geography, storeys, geography.buildingDefaults.weights);
                for (int count : counts) require(count >= 0);
                require(int(stackStoreys(counts).size()) == storeys);
                double footprint = averageBuildingArea(geography, DominantUse(use), Locality(place));
                std::vector<double> floors(size_t(storeys), footprint);
                DensityReport report =
                    densityReport(geography, DominantUse(use), Locality(place),
                                  averageLotArea(geography, DominantUse(use), Locality(place)), footprint, floors);
                require(std::isfinite(report.grz) && std::isfinite(report.gfz));
                (void)blockPlanParameters(geography, DominantUse(use), Locality(place));
            }
}

void cascadeFromTheCity(const UrbanGeography &geography, const PlanRandom &random) {
    for (int place = 0; place < kLocalities; ++place) {
        LandUseWeights district = childWeights(geography, geography.cityDefaults.weights, Locality(place), random);
        LandUseWeights block = blockWeights(geography, childWeights(geography, district, Locality(place), random));
        LandUseWeights lot = lotWeights(geography, block, random);
        for (double w : lot) require(w >= 0 && std::isfinite(w));
        Bauweise kind = bauweise(dominantUse(lot), Locality(place));
        RoofOrientation orientation = roofOrientation(kind, random);
        (void)alignment(kind, random);
        require(within(sideRatio(geography, orientation, random), geography.sideRatios[size_t(orientation)]));
        (void)roofKind(lot, 3 + place, random);
    }
    RoofDimensions roof = roofDimensions(geography, random);
    require(within(roof.height, geography.roof.height) && within(roof.eavesOverhang, geography.roof.eavesOverhang));
    require(within(sidewalkWidth(geography, random), geography.sidewalkWidth));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz::expectInputError([&] {
        UrbanGeography geography = parseUrbanGeography(fuzz::inputText(data, size), "fuzz.xml");
        PlanRandom random = parameterRandom(kSeed, uint32_t(size));
        buildingOfEveryKind(geography, random);
        cascadeFromTheCity(geography, random);
        for (PlanLevel level : {PlanLevel::City, PlanLevel::District, PlanLevel::Building, PlanLevel::Apartment})
            (void)lengthLimits(planParameters(geography, level));
        (void)citySize(geography, double(size) * 1000);
    });
    return 0;
}
