// The procedural twin of CityGML buildings: the FZK-Haus's (its file's figures), and the union
// of a building's ground surfaces.
#include <gtest/gtest.h>

#include "city/citygml_buildings.h"
#include "city/citygml_twin.h"
#include "city/footprint.h"
#include "geodesy/crs.h"
#include "shared_data.h"

namespace veduta {
namespace {

MapProjection utm32(double e, double n) { return MapProjection(crsByEpsg(25832), Georeference{25832, e, n}); }

// A polygon given in metres from 500000 E, 5400000 N (on UTM 32's central meridian).
CityGmlPolygon surface(SurfaceKind kind, std::vector<CrsCoordinate> ring) {
    for (CrsCoordinate &p : ring) p.x += 500000, p.y += 5400000;
    CityGmlPolygon polygon;
    polygon.kind = kind;
    polygon.rings = {std::move(ring)};
    return polygon;
}

TEST(CityGmlTwin, TheFzkHouse) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    CityGmlBuilding house = readCityGml(*file).buildings.at(0);
    std::vector<std::string> warnings;
    std::optional<TwinBuilding> twin = deriveTwin(house, utm32(458883, 5438358), warnings);
    ASSERT_TRUE(twin);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(twin->id, cityGmlBuildingId(house.id));
    ASSERT_EQ(twin->footprint.size(), 4u);  // its 12 × 10 m ground surface, about the origin
    EXPECT_NEAR(signedArea(twin->footprint), 120, 1e-3);
    EXPECT_DOUBLE_EQ(twin->base, -0.2);
    EXPECT_NEAR(twin->wallHeight, 3.43094010767585 + 0.2, 1e-12);
    EXPECT_NEAR(twin->roofHeight, 6.31769145362398 - 3.43094010767585, 1e-12);
    EXPECT_EQ(twin->roof, RoofType::Gable);
    EXPECT_EQ(twin->storeys, 2u);  // storeysAboveGround
    EXPECT_NEAR(twin->floorHeight, twin->wallHeight / 2, 1e-12);
}

TEST(CityGmlTwin, TheGroundOfTwoPartsIsOneOutline) {
    CityGmlBuilding building;
    building.id = "TWO";
    building.polygons.push_back(
        surface(SurfaceKind::Ground, {{0, 0, 0}, {0, 8, 0}, {6, 8, 0}, {6, 0, 0}}));  // facing down
    building.polygons.push_back(surface(SurfaceKind::Ground, {{6, 0, 0}, {6, 8, 0}, {10, 8, 0}, {10, 0, 0}}));
    building.polygons.push_back(surface(SurfaceKind::Roof, {{0, 0, 7}, {10, 0, 7}, {10, 8, 7}, {0, 8, 7}}));
    std::vector<std::string> warnings;
    std::optional<TwinBuilding> twin = deriveTwin(building, utm32(500000, 5400000), warnings);
    ASSERT_TRUE(twin) << (warnings.empty() ? "" : warnings[0]);
    // One rectangle: the shared edge's corners are dropped as points on a straight line.
    ASSERT_EQ(twin->footprint.size(), 4u);
    EXPECT_NEAR(signedArea(twin->footprint), 80, 1e-4);
    EXPECT_EQ(twin->wallHeight, 7);
    EXPECT_EQ(twin->roofHeight, 0);
    EXPECT_EQ(twin->roof, RoofType::Flat);
    EXPECT_EQ(twin->storeys, 2u);  // 7 m at 3.3 m a storey
}

TEST(CityGmlTwin, SeparatePiecesGiveTheLargestWithAWarning) {
    CityGmlBuilding building;
    building.id = "APART";
    building.polygons.push_back(surface(SurfaceKind::Ground, {{0, 0, 0}, {0, 8, 0}, {6, 8, 0}, {6, 0, 0}}));
    building.polygons.push_back(surface(SurfaceKind::Ground, {{20, 0, 0}, {20, 2, 0}, {22, 2, 0}, {22, 0, 0}}));
    building.polygons.push_back(surface(SurfaceKind::Wall, {{0, 0, 0}, {6, 0, 0}, {6, 0, 5}, {0, 0, 5}}));
    std::vector<std::string> warnings;
    std::optional<TwinBuilding> twin = deriveTwin(building, utm32(500000, 5400000), warnings);
    ASSERT_TRUE(twin);
    EXPECT_NEAR(signedArea(twin->footprint), 48, 1e-4);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("2 separate pieces"), std::string::npos) << warnings[0];
}

TEST(CityGmlTwin, NoOutlineNoTwin) {
    CityGmlBuilding building;
    building.id = "WALL";
    building.polygons.push_back(surface(SurfaceKind::Wall, {{0, 0, 0}, {6, 0, 0}, {6, 0, 5}, {0, 0, 5}}));
    std::vector<std::string> warnings;
    EXPECT_FALSE(deriveTwin(building, utm32(500000, 5400000), warnings));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("no twin"), std::string::npos);
}

}  // namespace
}  // namespace veduta
