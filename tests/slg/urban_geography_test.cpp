// Schrader's urban-geography cascade and its table file (digest-003 §4, §8.2).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "core/input_file.h"
#include "input_error.h"
#include "slg/urban_geography.h"
#include "slg/urban_geography_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

constexpr int kSeeds = 400;

const std::string &shippedPath() {
    static const std::string path = test::sourceFile("rules/slg/urban-geography.xml");
    return path;
}

const UrbanGeography &shipped() {
    static const UrbanGeography geography = readUrbanGeography(shippedPath());
    return geography;
}

LandUseWeights weights(double industrie, double wohnen, double buero, double einzelhandel, double gastronomie,
                       double freiflaeche) {
    return {industrie, wohnen, buero, einzelhandel, gastronomie, freiflaeche};
}

double of(const LandUseWeights &w, LandUse use) { return w[size_t(use)]; }
int of(const StoreysPerUse &counts, StoreyUse use) { return counts[size_t(use)]; }

TEST(UrbanGeography, LocalityOfChildrenByTheirDistance) {
    // Digest §8.2: children at 0.3, 0.5 and 0.7 d_max.
    EXPECT_EQ(locality(0.3 * 90, 90), Locality::Kern);
    EXPECT_EQ(locality(0.5 * 90, 90), Locality::Mantel);
    EXPECT_EQ(locality(0.7 * 90, 90), Locality::Rand);
    // Eq 38's bounds are strict: a third and two thirds are still the Mantel.
    EXPECT_EQ(locality(1, 3), Locality::Mantel);
    EXPECT_EQ(locality(2, 3), Locality::Mantel);
}

TEST(UrbanGeography, CitySizeByInhabitants) {
    EXPECT_EQ(citySize(shipped(), 800), CitySize::Landstadt);
    EXPECT_EQ(citySize(shipped(), 5000), CitySize::Landstadt);  // Table 1: a Kleinstadt has more than 5,000
    EXPECT_EQ(citySize(shipped(), 5001), CitySize::Kleinstadt);
    EXPECT_EQ(citySize(shipped(), 100000), CitySize::Mittelstadt);
    EXPECT_EQ(citySize(shipped(), 100001), CitySize::Grossstadt);
}

TEST(UrbanGeography, SharesAreWeightsOverTheirSum) {
    LandUseWeights percent = shares(weights(1, 2, 1, 0, 0, 0));
    EXPECT_DOUBLE_EQ(of(percent, LandUse::Wohnen), 50);
    EXPECT_DOUBLE_EQ(of(percent, LandUse::Industrie), 25);
    EXPECT_DOUBLE_EQ(of(shares(LandUseWeights{}), LandUse::Wohnen), 0);
}

TEST(UrbanGeography, DominantUseNeedsHalfTheWeight) {
    EXPECT_EQ(dominantUse(weights(50, 30, 10, 10, 0, 0)), DominantUse::Industriegebiet);
    EXPECT_EQ(dominantUse(weights(0, 45, 30, 25, 0, 0)), DominantUse::Gewerbegebiet);  // Büro + EH = 55 %
    EXPECT_EQ(dominantUse(shipped().blockDefaults.weights), DominantUse::Wohngebiet);  // Table 10: Wohnen 75 %
    // Table 14: Wohnen 50 %, Büro and EH 50 % together; the tie goes to the housing.
    EXPECT_EQ(dominantUse(shipped().buildingDefaults.weights), DominantUse::Wohngebiet);
    EXPECT_EQ(dominantUse(weights(50, 0, 25, 25, 0, 0)), DominantUse::Industriegebiet);
    EXPECT_EQ(dominantUse(weights(40, 40, 20, 0, 0, 0)), DominantUse::Mischgebiet);
    EXPECT_EQ(dominantUse(shipped().cityDefaults.weights), DominantUse::Mischgebiet);  // Table 5: Wohnen 40 %
    EXPECT_EQ(dominantUse(weights(10, 20, 0, 0, 0, 70)), DominantUse::Unbebaut);
    EXPECT_EQ(dominantUse(LandUseWeights{}), DominantUse::Unbebaut);
}

TEST(UrbanGeography, ChildWeightsStayWithinTheirLocalitysFactors) {
    LandUseWeights parent = weights(10, 20, 30, 40, 50, 60);
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        PlanRandom random = parameterRandom(seed, 11);
        LandUseWeights kern = childWeights(shipped(), parent, Locality::Kern, random);
        EXPECT_GE(of(kern, LandUse::Buero), 0.5 * 30);  // eq 41: rand(0.5, 1.5)
        EXPECT_LE(of(kern, LandUse::Buero), 1.5 * 30);
        EXPECT_LE(of(kern, LandUse::Industrie), 0.5 * 10);  // rand(0, 0.5)
        LandUseWeights fringe = childWeights(shipped(), parent, Locality::Rand, random);
        EXPECT_GE(of(fringe, LandUse::Wohnen), 0.5 * 20);  // eq 39: rand(0.5, 1.5)
        EXPECT_LE(of(fringe, LandUse::Buero), 0.5 * 30);   // rand(0, 0.5)
        LandUseWeights mantel = childWeights(shipped(), parent, Locality::Mantel, random);
        for (int use = 0; use < kLandUses; ++use) EXPECT_LE(mantel[size_t(use)], parent[size_t(use)]);  // eq 40
    }
}

TEST(UrbanGeography, BlockMaskKeepsWhatItsDominantUseAllows) {
    // Eq 44: an Industriegebiet keeps Industrie and Freifläche only.
    LandUseWeights block = blockWeights(shipped(), weights(60, 10, 10, 10, 5, 5));
    EXPECT_EQ(block, weights(60, 0, 0, 0, 0, 5));
    // A Wohngebiet drops Industrie and Büro.
    EXPECT_EQ(blockWeights(shipped(), weights(5, 60, 10, 10, 10, 5)), weights(0, 60, 0, 10, 10, 5));
}

TEST(UrbanGeography, LotWeightsAreDrawnBelowTheBlocksAndMasked) {
    // Eq 47–48 on a Wohngebiet block: Industrie, Büro and Freifläche go, the rest is rand(0, 1) of it.
    LandUseWeights block = weights(5, 60, 10, 10, 10, 5);
    bool varied = false;
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        LandUseWeights lot = lotWeights(shipped(), block, parameterRandom(seed, 3));
        EXPECT_EQ(of(lot, LandUse::Industrie), 0);
        EXPECT_EQ(of(lot, LandUse::Buero), 0);
        EXPECT_EQ(of(lot, LandUse::Freiflaeche), 0);
        EXPECT_LE(of(lot, LandUse::Wohnen), 60);
        varied |= of(lot, LandUse::Wohnen) != of(lotWeights(shipped(), block, parameterRandom(0, 3)), LandUse::Wohnen);
    }
    EXPECT_TRUE(varied);
}

TEST(UrbanGeography, AverageLotAndBuildingAreas) {
    EXPECT_EQ(averageLotArea(shipped(), DominantUse::Wohngebiet, Locality::Kern), 150);  // eq 45
    EXPECT_EQ(averageLotArea(shipped(), DominantUse::Mischgebiet, Locality::Rand), 200);
    EXPECT_EQ(averageLotArea(shipped(), DominantUse::Industriegebiet, Locality::Mantel), 300);
    EXPECT_EQ(averageBuildingArea(shipped(), DominantUse::Mischgebiet, Locality::Mantel), 100);  // eq 46
    EXPECT_EQ(averageBuildingArea(shipped(), DominantUse::Gewerbegebiet, Locality::Kern), 200);
}

TEST(UrbanGeography, BauweiseByUseAndLocality) {
    // Eq 57.
    for (int use = 0; use < kDominantUses; ++use) {
        EXPECT_EQ(bauweise(DominantUse(use), Locality::Kern), Bauweise::Closed);
        EXPECT_EQ(bauweise(DominantUse(use), Locality::Rand), Bauweise::Open);
    }
    EXPECT_EQ(bauweise(DominantUse::Wohngebiet, Locality::Mantel), Bauweise::SemiOpen);
    EXPECT_EQ(bauweise(DominantUse::Mischgebiet, Locality::Mantel), Bauweise::SemiOpen);
    EXPECT_EQ(bauweise(DominantUse::Industriegebiet, Locality::Mantel), Bauweise::Open);
    EXPECT_EQ(bauweise(DominantUse::Gewerbegebiet, Locality::Mantel), Bauweise::Open);
}

TEST(UrbanGeography, PlacementOfTheBuildingOnItsLot) {
    std::set<Alignment> alignments;
    std::set<RoofOrientation> orientations;
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        PlanRandom random = parameterRandom(seed, 5);
        // Eq 49–50: a closed or semi-open row stands at the front, gable to the street.
        EXPECT_EQ(alignment(Bauweise::Closed, random), Alignment::Front);
        EXPECT_EQ(alignment(Bauweise::SemiOpen, random), Alignment::Front);
        EXPECT_EQ(roofOrientation(Bauweise::SemiOpen, random), RoofOrientation::Giebelstaendig);
        alignments.insert(alignment(Bauweise::Open, random));
        RoofOrientation orientation = roofOrientation(Bauweise::Open, random);
        orientations.insert(orientation);
        // Eq 51: eaves to the street make the front the longer side.
        double ratio = sideRatio(shipped(), orientation, random);
        if (orientation == RoofOrientation::Traufstaendig) {
            EXPECT_GE(ratio, 2.0 / 3);
            EXPECT_LE(ratio, 1);
        } else {
            EXPECT_GE(ratio, 1);
            EXPECT_LE(ratio, 5.0 / 3);
        }
        double sidewalk = sidewalkWidth(shipped(), random);  // Table 11
        EXPECT_GE(sidewalk, 2.5);
        EXPECT_LE(sidewalk, 3);
    }
    EXPECT_EQ(alignments.size(), 3u);
    EXPECT_EQ(orientations.size(), 2u);
}

// The smallest and largest count drawn over many seeds, and how many values were drawn.
struct Drawn {
    int low = 1 << 30, high = -1;
    std::set<int> values;
};
Drawn drawnStoreys(std::optional<CitySize> city, DominantUse use, Locality place) {
    Drawn drawn;
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        int n = storeyCount(shipped(), city, use, place, parameterRandom(seed, 17));
        drawn.low = std::min(drawn.low, n);
        drawn.high = std::max(drawn.high, n);
        drawn.values.insert(n);
    }
    return drawn;
}

TEST(UrbanGeography, StoreyCountsReachEveryValueOfTheirRangeAndNoOther) {
    for (int city = 0; city < kCitySizes; ++city)
        for (int use = 0; use < kDominantUses; ++use)
            for (int place = 0; place < kLocalities; ++place) {
                StoreyRange range = shipped().storeyCounts[size_t(city)][size_t(use)][size_t(place)];
                Drawn drawn = drawnStoreys(CitySize(city), DominantUse(use), Locality(place));
                EXPECT_EQ(drawn.low, range.base);
                EXPECT_EQ(drawn.high, range.base + range.extra);
                EXPECT_EQ(int(drawn.values.size()), range.extra + 1);
            }
}

TEST(UrbanGeography, StoreyCountsOfTheThesis) {
    // Eq 59: 5 + r(0, 10) for offices in a Großstadt's Kern; eq 61: 1 + r(0, 1) at a Kleinstadt's
    // Rand; no city: a Mittelstadt, eq 60's 2 + r(0, 2) for a Wohngebiet in the Mantel.
    Drawn offices = drawnStoreys(CitySize::Grossstadt, DominantUse::Gewerbegebiet, Locality::Kern);
    EXPECT_EQ(offices.low, 5);
    EXPECT_EQ(offices.high, 15);
    Drawn houses = drawnStoreys(CitySize::Kleinstadt, DominantUse::Wohngebiet, Locality::Rand);
    EXPECT_EQ(houses.low, 1);
    EXPECT_EQ(houses.high, 2);
    Drawn noCity = drawnStoreys(std::nullopt, DominantUse::Wohngebiet, Locality::Mantel);
    EXPECT_EQ(noCity.values, (std::set<int>{2, 3, 4}));
}

TEST(UrbanGeography, SixStoreysHalfFlatsHalfOffices) {
    // L3089: three storeys of each.
    StoreysPerUse counts = storeysPerUse(shipped(), 6, weights(0, 50, 50, 0, 0, 0));
    EXPECT_EQ(of(counts, StoreyUse::Buero), 3);
    EXPECT_EQ(of(counts, StoreyUse::Wohnen), 3);
    EXPECT_EQ(stackStoreys(counts),
              (std::vector<StoreyUse>{StoreyUse::Buero, StoreyUse::Buero, StoreyUse::Buero, StoreyUse::Wohnen,
                                      StoreyUse::Wohnen, StoreyUse::Wohnen}));
}

TEST(UrbanGeography, Table14sBuildingStacksOfficesUnderFlats) {
    // Digest §8.2: Wohnen 50, Büro 40, EH 10 (a Wohngebiet in a Mittelstadt's Mantel, 2–4
    // storeys): ⌊4·10/100 + .5⌋ = 0 shops, ⌊4·40/90 + .5⌋ = 2 offices, 2 flats.
    const LandUseWeights &table14 = shipped().buildingDefaults.weights;
    ASSERT_EQ(table14, weights(0, 50, 40, 10, 0, 0));
    ASSERT_EQ(shipped().buildingDefaults.locality, Locality::Mantel);
    using enum StoreyUse;
    EXPECT_EQ(stackStoreys(storeysPerUse(shipped(), 4, table14)),
              (std::vector<StoreyUse>{Buero, Buero, Wohnen, Wohnen}));
    EXPECT_EQ(stackStoreys(storeysPerUse(shipped(), 3, table14)), (std::vector<StoreyUse>{Buero, Wohnen, Wohnen}));
    EXPECT_EQ(entranceSide(Buero), EntranceSide::Street);
}

TEST(UrbanGeography, ShopsOrRestaurantsGoAtTheBottomAndAreCapped) {
    // Eq 62: EH ⌊min(8·60/100, 2) + .5⌋ = 2 (capped), Gastro dropped for the larger EH weight,
    // then Industrie ⌊6·20/20 + .5⌋ = 6 of what is left.
    using enum StoreyUse;
    StoreysPerUse counts = storeysPerUse(shipped(), 8, weights(20, 0, 0, 60, 20, 0));
    EXPECT_EQ(stackStoreys(counts),
              (std::vector<StoreyUse>{Einzelhandel, Einzelhandel, Industrie, Industrie, Industrie, Industrie, Industrie,
                                      Industrie}));
    // A tie between shops and restaurants: ⌊min(4·25/100, 1) + .5⌋ = 1 restaurant, no shop.
    EXPECT_EQ(stackStoreys(storeysPerUse(shipped(), 4, weights(0, 50, 0, 25, 25, 0))),
              (std::vector<StoreyUse>{Gastronomie, Wohnen, Wohnen, Wohnen}));
    EXPECT_EQ(entranceSide(Gastronomie), EntranceSide::Rear);  // eq 58
    EXPECT_EQ(entranceSide(Einzelhandel), EntranceSide::Rear);
}

TEST(UrbanGeography, StoreysAlwaysAddUpToTheCount) {
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        PlanRandom random = parameterRandom(seed, 23);
        LandUseWeights lot = childWeights(shipped(), shipped().cityDefaults.weights, Locality::Mantel, random);
        for (int n = 0; n <= 15; ++n) {
            StoreysPerUse counts = storeysPerUse(shipped(), n, lot);
            EXPECT_EQ(int(stackStoreys(counts).size()), n);
            EXPECT_LE(of(counts, StoreyUse::Einzelhandel), 2);
            EXPECT_LE(of(counts, StoreyUse::Gastronomie), 1);
            EXPECT_TRUE(of(counts, StoreyUse::Einzelhandel) == 0 || of(counts, StoreyUse::Gastronomie) == 0);
        }
    }
}

TEST(UrbanGeography, RoofKindByUse) {
    std::set<RoofKind> industrial;
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        PlanRandom random = parameterRandom(seed, 29);
        industrial.insert(roofKind(weights(10, 90, 0, 0, 0, 0), 4, random));  // eq 63: 50/50
        EXPECT_EQ(roofKind(weights(0, 40, 50, 10, 0, 0), 4, random), RoofKind::Flat);
        EXPECT_EQ(roofKind(weights(0, 50, 40, 10, 0, 0), 4, random), RoofKind::Gable);
        EXPECT_EQ(roofKind(weights(0, 50, 40, 10, 0, 0), 6, random), RoofKind::Tent);  // not four corners
        EXPECT_EQ(roofKind(weights(0, 50, 40, 10, 0, 0), 3, random), RoofKind::Tent);
        EXPECT_NE(roofKind(weights(10, 90, 0, 0, 0, 0), 5, random), RoofKind::Gable);
    }
    EXPECT_EQ(industrial, (std::set<RoofKind>{RoofKind::Flat, RoofKind::Gable}));
}

TEST(UrbanGeography, RoofDimensionsWithinEquation64) {
    std::set<double> heights;
    for (uint32_t seed = 0; seed < kSeeds; ++seed) {
        RoofDimensions roof = roofDimensions(shipped(), parameterRandom(seed, 31));
        EXPECT_GE(roof.height, 2.5);
        EXPECT_LE(roof.height, 3.5);
        EXPECT_EQ(roof.thickness, 0.15);
        EXPECT_GE(roof.gableOverhang, 0.1);
        EXPECT_LE(roof.gableOverhang, 0.25);
        EXPECT_GE(roof.eavesOverhang, 1);
        EXPECT_LE(roof.eavesOverhang, 1.5);
        heights.insert(roof.height);
    }
    EXPECT_GT(heights.size(), size_t(kSeeds / 2));
}

TEST(UrbanGeography, LengthLimitsOfEachLevelsTable) {
    // Tables 4, 6, 13, 16 through eq 21–22 (digest §4.3).
    LengthLimits city = lengthLimits(planParameters(shipped(), PlanLevel::City));
    EXPECT_NEAR(city.minimum, 111.8, 0.05);
    EXPECT_NEAR(city.maximum, 316.2, 0.05);
    LengthLimits district = lengthLimits(planParameters(shipped(), PlanLevel::District));
    EXPECT_NEAR(district.minimum, 50, 1e-9);
    EXPECT_NEAR(district.maximum, 141.4, 0.05);
    LengthLimits storey = lengthLimits(planParameters(shipped(), PlanLevel::Building));
    EXPECT_NEAR(storey.minimum, 3.87, 0.005);
    EXPECT_NEAR(storey.maximum, 10.95, 0.005);
    LengthLimits apartment = lengthLimits(planParameters(shipped(), PlanLevel::Apartment));
    EXPECT_NEAR(apartment.minimum, 1.83, 0.005);
    EXPECT_NEAR(apartment.maximum, 9.49, 0.005);
}

TEST(UrbanGeography, PlanParametersOfTheTables) {
    PlanParameters storey = planParameters(shipped(), PlanLevel::Building);
    EXPECT_EQ(storey.rule, LandmarkRule::Growth);
    EXPECT_EQ(storey.gap, GapType::HouseCorridor);
    EXPECT_EQ(landmarkCount(storey, 100, 40, 4), 2);  // (15; 2): two apartments on 100 m²
    PlanParameters apartment = planParameters(shipped(), PlanLevel::Apartment);
    EXPECT_EQ(landmarkCount(apartment, 343, 74, 4), 7);
    EXPECT_EQ(reflexLimit(planParameters(shipped(), PlanLevel::District), SlgPathType::BorderWithCorner), 1);
    EXPECT_EQ(planParameters(shipped(), PlanLevel::City).gapWidth, 20);
}

TEST(UrbanGeography, PerimeterRuleGivesTheBlock28Lots) {
    // A 100 × 100 m block, Kern Wohngebiet: eq 45's 150 m² lots, ⌊400/√150 − 4⌋ = 28.
    PlanParameters block = blockPlanParameters(shipped(), DominantUse::Wohngebiet, Locality::Kern);
    EXPECT_EQ(block.averageArea, 150);
    EXPECT_EQ(block.rule, LandmarkRule::Perimeter);
    EXPECT_EQ(block.gap, GapType::None);
    EXPECT_EQ(landmarkCount(block, 100 * 100, 400, 4), 28);
    // In the Rand the lots are 200 m²: ⌊400/√200 − 4⌋ = 24.
    EXPECT_EQ(landmarkCount(blockPlanParameters(shipped(), DominantUse::Wohngebiet, Locality::Rand), 1e4, 400, 4), 24);
}

TEST(UrbanGeography, RetailGroundFloorOfTable15) {
    std::optional<StoreyParameters> shop = storeyParameters(shipped(), StoreyUse::Einzelhandel, 0);
    ASSERT_TRUE(shop);
    EXPECT_EQ(shop->height, 3);
    EXPECT_EQ(shop->fitOut, FitOut::Apartments);
    EXPECT_EQ(shop->frontWindows.placement, WindowArrangement::Contiguous);
    EXPECT_FALSE(shop->frontWindows.canopyDepth);
    EXPECT_EQ(shop->backWindows.canopyDepth, 1.7);
    EXPECT_EQ(shop->outerDoor.alignment, DoorAlignment::Left);
    EXPECT_FALSE(storeyParameters(shipped(), StoreyUse::Einzelhandel, 1));  // no upper floor of shops given
    EXPECT_EQ(shipped().wallThickness, 0.3);                                // Table 12
    EXPECT_EQ(shipped().stairwellArea, 5);
}

TEST(UrbanGeography, DensityReportOfAHandExample) {
    // Eq 1's example: a 200 m² lot with two storeys of 100 m² has GRZ 0.5 and GFZ 1.0, over a
    // Wohngebiet's GRZ cap of 0.4 (Table 2), which the report shows and does not judge.
    std::vector<double> storeys = {100, 100};
    DensityReport report = densityReport(shipped(), DominantUse::Wohngebiet, Locality::Mantel, 200, 100, storeys);
    EXPECT_DOUBLE_EQ(report.grz, 0.5);
    EXPECT_DOUBLE_EQ(report.gfz, 1.0);
    ASSERT_TRUE(report.zone);
    EXPECT_EQ(report.zone->name, "Wohngebiet");
    EXPECT_EQ(report.zone->grz, 0.4);
    EXPECT_EQ(report.zone->gfz, 1.2);
    EXPECT_EQ(densityReport(shipped(), DominantUse::Mischgebiet, Locality::Kern, 150, 125, storeys).zone->gfz, 3.0);
    EXPECT_FALSE(densityReport(shipped(), DominantUse::Unbebaut, Locality::Rand, 200, 0, {}).zone);
}

TEST(UrbanGeography, SameIdentityAndSeedGiveTheSameDraws) {
    LandUseWeights parent = shipped().districtDefaults.weights;
    LandUseWeights first = childWeights(shipped(), parent, Locality::Kern, parameterRandom(9, 1234));
    // Other objects' draws in between change nothing: a draw depends on seed and identity only.
    for (uint32_t other = 0; other < 10; ++other)
        (void)childWeights(shipped(), parent, Locality::Kern, parameterRandom(9, other));
    EXPECT_EQ(childWeights(shipped(), parent, Locality::Kern, parameterRandom(9, 1234)), first);
    EXPECT_NE(childWeights(shipped(), parent, Locality::Kern, parameterRandom(9, 1235)), first);
    EXPECT_NE(childWeights(shipped(), parent, Locality::Kern, parameterRandom(10, 1234)), first);
    // The cascade's draws are its own stream's: the SLG plan's jitter with the same seed and
    // identity draws other numbers.
    EXPECT_NE(parameterRandom(9, 1234).unit(1), PlanRandom(9, 1234, RandomStream::SlgPlan).unit(1));
}

// The shipped file with `from` replaced by `to` (once), and where `to` then starts.
struct Edited {
    std::string text;
    int line = 0, column = 0;
};
Edited edited(const std::string &from, const std::string &to) {
    Edited result{readInputFile(shippedPath())};
    size_t at = result.text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    result.text.replace(at, from.size(), to);
    result.line = 1 + int(std::count(result.text.begin(), result.text.begin() + long(at), '\n'));
    result.column = int(at - result.text.rfind('\n', at));
    return result;
}

std::string errorOf(const std::string &text) {
    return test::inputErrorOf([&] { parseUrbanGeography(text, "tables.xml"); });
}

std::string place(const Edited &e, size_t offset) {
    return "tables.xml:" + std::to_string(e.line) + ":" + std::to_string(e.column + int(offset)) + ": ";
}

TEST(UrbanGeographyFile, ShippedFileReads) { EXPECT_EQ(errorOf(readInputFile(shippedPath())), "no error"); }

TEST(UrbanGeographyFile, BadNumberIsReportedAtItsValue) {
    Edited e = edited("area=\"175\"", "area=\"17x\"");
    EXPECT_EQ(errorOf(e.text), place(e, 6) + "'17x' is not a number (attribute 'area')");
}

TEST(UrbanGeographyFile, RangeMustNotRunBackwards) {
    Edited e = edited("height=\"2.5 3.5\"", "height=\"3.5 2.5\"");
    EXPECT_EQ(errorOf(e.text), place(e, 8) + "attribute 'height' is a range a b with a <= b, not 3.5 > 2.5");
}

TEST(UrbanGeographyFile, MissingTableIsReportedAtTheRoot) {
    Edited e = edited(
        "<roof height=\"2.5 3.5\" thickness=\"0.15\" gable-overhang=\"0.1 0.25\" eaves-overhang=\"1 1.5\"/>", "");
    Edited root = edited("<urban-geography>", "<urban-geography>");
    EXPECT_EQ(errorOf(e.text), place(root, 0) + "<urban-geography> has no <roof>");
}

TEST(UrbanGeographyFile, EveryCellOfATableIsNeeded) {
    Edited e = edited("    <count use=\"Wohngebiet\" locality=\"Rand\" base=\"2\" extra=\"1\"/>\n", "");
    Edited counts = edited("<storey-counts city=\"Grossstadt\">", "<storey-counts city=\"Grossstadt\">");
    EXPECT_EQ(errorOf(e.text), place(counts, 0) + "no <count> for Wohngebiet in the Rand");
}

TEST(UrbanGeographyFile, ChecksOfValues) {
    auto errorAfter = [](const std::string &from, const std::string &to) { return errorOf(edited(from, to).text); };
    EXPECT_NE(errorAfter("wohnen=\"40\"", "wohnen=\"-40\"").find("outside [0, "), std::string::npos);
    EXPECT_NE(errorAfter("extra=\"10\"", "extra=\"1000\"").find("outside [0, 200]"), std::string::npos);
    EXPECT_NE(errorAfter("keeps=\"industrie\"", "keeps=\"industry\"").find("'industry' is not a land use"),
              std::string::npos);
    EXPECT_NE(errorAfter("locality=\"Kern\" industrie=\"0 0.5\"", "locality=\"Mantel\" industrie=\"0 0.5\"")
                  .find("<child-factors locality=\"Mantel\"> is given twice"),
              std::string::npos);
    EXPECT_NE(errorAfter("scale=\"15\"", "scale=\"0\"").find("divides by the scale"), std::string::npos);
    EXPECT_NE(errorAfter("side-ratio=\"1/3\"", "side-ratio=\"1/0\"").find("'1/0' divides by 0"), std::string::npos);
    EXPECT_NE(errorAfter("jitter=\"0.1\"", "jitter=\"0.5\"").find("landmarks swap places"), std::string::npos);
    EXPECT_NE(errorAfter("inhabitants-above=\"20000\"", "inhabitants-above=\"2000\"")
                  .find("a Mittelstadt needs more inhabitants than a Kleinstadt"),
              std::string::npos);
    EXPECT_NE(errorAfter("<building ", "<building storeys=\"3\" ").find("unknown attribute 'storeys'"),
              std::string::npos);
    EXPECT_NE(errorAfter("zone=\"Kerngebiet\"", "zone=\"Altstadt\"").find("no <zone name=\"Altstadt\">"),
              std::string::npos);
}

}  // namespace
}  // namespace veduta
