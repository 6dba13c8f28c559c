// Known answers of the building measures of `veduta compare` (issue 18): a 10 × 10 × 10 m box
// against itself, moved by 1 m and 10 % taller, with and without recorded ground plans, and
// paired by overlap when the ids differ.
#include <gtest/gtest.h>

#include "compare/building_comparison.h"
#include "compare/height_map.h"
#include "scene/shapes.h"

namespace veduta {
namespace {

// A box standing on z = 0 over [x, x + 10] × [0, 10], as its generator would record it.
RenderScene boxScene(uint32_t id, float x, float height, bool withPlan = true) {
    RenderSceneBuilder builder;
    ShapeSpec spec;
    spec.kind = ShapeKind::Box;
    spec.size = {10, 10, height};
    Mesh box = makeShape(spec);  // centred on x and y, standing on z = 0
    builder.addMesh(box, Transform::translate({x + 5, 5, 0}), 1, id);
    BuildingRecord record{id, 0, height, height, "flat", {}};
    if (withPlan) record.footprint = {{{x, 0}, {x + 10, 0}, {x + 10, 10}, {x, 10}}};
    builder.recordBuilding(record);
    return std::move(builder).build();
}

BuildingComparison compare(const RenderScene &a, const RenderScene &b) {
    GroundGrid grid = gridOverBuildings(a, b, 4'000'000);
    return compareBuildings(a, topDownHeights(a, grid), b, topDownHeights(b, grid));
}

const BuildingPair &onlyPair(const BuildingComparison &c) {
    EXPECT_EQ(c.pairs.size(), 1u);
    return c.pairs.at(0);
}

TEST(BuildingComparison, ABoxAgainstItself) {
    RenderScene a = boxScene(7, 0, 10);
    BuildingComparison c = compare(a, a);
    EXPECT_TRUE(c.groundPlans);
    EXPECT_EQ(c.matchedById, 1u);
    const BuildingPair &p = onlyPair(c);
    EXPECT_EQ(p.matchedBy, "id");
    EXPECT_DOUBLE_EQ(p.footprintIou, 1);
    EXPECT_EQ(*p.eavesError, 0);
    EXPECT_EQ(*p.ridgeError, 0);
    EXPECT_NEAR(*p.volumeError, 0, 1e-12);
    EXPECT_TRUE(*p.roofAgrees);
    EXPECT_NEAR(p.a->volume, 1000, 1e-3);
    EXPECT_NEAR(p.a->footprintArea, 100, 1e-6);
}

TEST(BuildingComparison, ABoxMovedByAMetre) {
    for (bool plans : {true, false}) {
        SCOPED_TRACE(plans ? "ground plans" : "seen from above");
        BuildingComparison c = compare(boxScene(7, 0, 10, plans), boxScene(7, 1, 10, plans));
        EXPECT_EQ(c.groundPlans, plans);
        const BuildingPair &p = onlyPair(c);
        // They share 9 × 10 m of the 11 × 10 m they cover together.
        EXPECT_NEAR(p.footprintIou, 90.0 / 110.0, 1e-9);
        EXPECT_EQ(*p.eavesError, 0);
        EXPECT_NEAR(*p.volumeError, 0, 1e-9);
    }
}

TEST(BuildingComparison, ABoxTenPercentTaller) {
    BuildingComparison c = compare(boxScene(7, 0, 10), boxScene(7, 0, 11));
    const BuildingPair &p = onlyPair(c);
    EXPECT_DOUBLE_EQ(p.footprintIou, 1);
    EXPECT_FLOAT_EQ(float(*p.eavesError), 1);
    EXPECT_FLOAT_EQ(float(*p.ridgeError), 1);
    EXPECT_NEAR(*p.volumeError, 0.1, 1e-6);
    EXPECT_NEAR(c.meanAbsVolumeError, 0.1, 1e-6);
}

TEST(BuildingComparison, BuildingsOfOtherIdsArePairedByOverlap) {
    BuildingComparison c = compare(boxScene(7, 0, 10), boxScene(8, 1, 10));
    const BuildingPair &p = onlyPair(c);
    EXPECT_EQ(p.matchedBy, "overlap");
    EXPECT_EQ(c.matchedByOverlap, 1u);
    EXPECT_NEAR(p.footprintIou, 90.0 / 110.0, 1e-9);
}

TEST(BuildingComparison, ABuildingWithoutPartnerStaysAlone) {
    BuildingComparison c = compare(boxScene(7, 0, 10), boxScene(8, 30, 10));
    ASSERT_EQ(c.pairs.size(), 2u);
    EXPECT_EQ(c.onlyA, 1u);
    EXPECT_EQ(c.onlyB, 1u);
    EXPECT_EQ(c.pairs[0].footprintIou, 0);
    EXPECT_FALSE(c.pairs[0].b);
    EXPECT_FALSE(c.pairs[1].a);
}

}  // namespace
}  // namespace veduta
