// What CityGML buildings measure: heights, volume, footprint and roof type, worked out by hand
// for the FZK-Haus (its file's coordinates) and a 10 × 8 × 6 m box.
#include <gtest/gtest.h>

#include "city/citygml_measures.h"
#include "shared_data.h"
#include "test_paths.h"

namespace veduta {
namespace {

TEST(CityGmlMeasures, TheFzkHouse) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    BuildingMeasures m = measureBuilding(readCityGml(*file).buildings.at(0));
    EXPECT_EQ(m.ground, -0.2);
    EXPECT_EQ(m.eaves, 3.43094010767585);
    EXPECT_EQ(m.ridge, 6.31769145362398);
    ASSERT_TRUE(m.volume);
    // 12 × 10 m up to the eaves, and the gable roof's prism 10 m wide, 2.887 m high, 12 m long.
    EXPECT_NEAR(*m.volume, 120 * (m.eaves + 0.2) + 0.5 * 10 * (m.ridge - m.eaves) * 12, 1e-6);
    ASSERT_EQ(m.footprint.size(), 1u);
    EXPECT_NEAR(groundArea(m.footprint[0]), 120, 1e-6);  // counter-clockwise from above
    EXPECT_EQ(m.roofType, RoofType::Gable);              // CityGML's code 1030
}

TEST(CityGmlMeasures, ALod1Box) {
    BuildingMeasures m =
        measureBuilding(readCityGml(test::sourceFile("fuzz/corpus/citygml/lod1-box.gml")).buildings.at(0));
    EXPECT_EQ(m.ground, 0);
    EXPECT_EQ(m.eaves, 6);  // its top face is its roof
    EXPECT_EQ(m.ridge, 6);
    ASSERT_TRUE(m.volume);
    EXPECT_NEAR(*m.volume, 480, 1e-9);
    ASSERT_EQ(m.footprint.size(), 1u);
    EXPECT_NEAR(groundArea(m.footprint[0]), 80, 1e-9);
    EXPECT_EQ(m.roofType, RoofType::Flat);  // no roofType in the file: its level top, by the slopes
}

TEST(CityGmlMeasures, RoofTypeFromTheSlopes) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    EXPECT_EQ(roofTypeFromSlopes(readCityGml(*file).buildings.at(0)), RoofType::Gable);  // two opposite slopes
}

TEST(CityGmlMeasures, RoofTypeOfFourSlopesIsAHip) {
    // A 10 × 8 m hip roof from eaves at 6 m to a ridge at 9 m from (3, 4) to (7, 4).
    CityGmlBuilding building;
    auto face = [&](std::vector<CrsCoordinate> ring) {
        CityGmlPolygon polygon;
        polygon.kind = SurfaceKind::Roof;
        polygon.rings = {std::move(ring)};
        building.polygons.push_back(polygon);
    };
    face({{0, 0, 6}, {10, 0, 6}, {7, 4, 9}, {3, 4, 9}});
    face({{10, 0, 6}, {10, 8, 6}, {7, 4, 9}});
    face({{10, 8, 6}, {0, 8, 6}, {3, 4, 9}, {7, 4, 9}});
    face({{0, 8, 6}, {0, 0, 6}, {3, 4, 9}});
    EXPECT_EQ(roofTypeFromSlopes(building), RoofType::Hip);
    building.polygons.erase(building.polygons.begin() + 3);
    building.polygons.erase(building.polygons.begin() + 1);
    EXPECT_EQ(roofTypeFromSlopes(building), RoofType::Gable);
    building.polygons.pop_back();
    EXPECT_EQ(roofTypeFromSlopes(building), RoofType::Shed);
}

TEST(CityGmlMeasures, AnOpenModelHasNoVolume) {
    BuildingMeasures m =
        measureBuilding(readCityGml(test::sourceFile("fuzz/corpus/citygml/wall-with-hole.gml")).buildings.at(0));
    EXPECT_FALSE(m.volume);
    EXPECT_EQ(m.ridge, 6);
}

TEST(CityGmlMeasures, RoofCodesOfBothLists) {
    EXPECT_EQ(roofTypeOfCode("1000"), RoofType::Flat);
    EXPECT_EQ(roofTypeOfCode("3100"), RoofType::Gable);  // AdV Satteldach
    EXPECT_EQ(roofTypeOfCode("3200"), RoofType::Hip);
    EXPECT_EQ(roofTypeOfCode("3300"), RoofType::HalfHip);
    EXPECT_EQ(roofTypeOfCode("3400"), RoofType::Mansard);
    EXPECT_EQ(roofTypeOfCode("3500"), RoofType::Pyramid);
    EXPECT_EQ(roofTypeOfCode("2100"), RoofType::Shed);
    EXPECT_EQ(roofTypeOfCode("1030"), RoofType::Gable);  // CityGML gabled roof
    EXPECT_EQ(roofTypeOfCode("1040"), RoofType::Hip);
    EXPECT_EQ(roofTypeOfCode("1010"), RoofType::Shed);
    EXPECT_FALSE(roofTypeOfCode("3700"));  // Kuppeldach: a dome veduta does not build
    EXPECT_FALSE(roofTypeOfCode("5000"));  // Mischform
    EXPECT_FALSE(roofTypeOfCode(""));
}

}  // namespace
}  // namespace veduta
