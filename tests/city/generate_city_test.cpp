// <city> in scene files: seed 000's Listing 2.1 built into lots, buildings and streets.
#include <gtest/gtest.h>

#include <set>

#include "city/generate_city.h"
#include "assembly/build_scene.h"

namespace veduta {
namespace {

RenderScene build(const std::string &xml, std::vector<std::string> *warnings = nullptr) {
    return buildRenderScene(readSceneText(xml, "test.xml", VEDUTA_SOURCE_DIR "/scenes"), warnings);
}

TEST(GenerateCity, ListingTwoOneBecomesLotsBuildingsAndStreets) {
    std::vector<std::string> warnings;
    RenderScene scene = build("<scene version=\"1\"><city file=\"../cities/bilke-listing-2-1.xml\" seed=\"1909\"/>"
                              "<buildings rules=\"../rules/gruenderzeit/FacadeStructure.xml\"><building id=\"5\" "
                              "footprint=\"-60 -60 -45 -60 -45 -48 -60 -48\" street=\"0\"/></buildings></scene>",
                              &warnings);
    std::set<uint32_t> buildings;
    for (const BakedMesh &m : scene.meshes) buildings.insert(m.buildingId);
    // The scene's own building keeps 5; the city's take 6 on: the given lot and the lots cut
    // from the first block; the streets are no building.
    EXPECT_TRUE(buildings.count(5));
    EXPECT_TRUE(buildings.count(0));
    EXPECT_GE(buildings.size(), 4u);
    EXPECT_EQ(*buildings.rbegin(), 5 + buildings.size() - 2);
    bool clockwise = false;
    for (const std::string &w : warnings) clockwise |= w.find("bilke-listing-2-1.xml:63:7: the block runs clockwise") != std::string::npos;
    EXPECT_TRUE(clockwise);
}

TEST(GenerateCity, AnOpenStreetMapFileIsACityWithTheRulesOfItsElement) {
    std::vector<std::string> warnings;
    RenderScene scene = build("<scene version=\"1\"><city file=\"../tests/data/osm/small-district.osm\" "
                              "rules=\"../rules/gruenderzeit/FacadeStructure.xml\" seed=\"3\"/></scene>",
                              &warnings);
    std::set<uint32_t> buildings;
    for (const BakedMesh &m : scene.meshes) buildings.insert(m.buildingId);
    EXPECT_TRUE(buildings.count(0));  // the streets
    EXPECT_GE(buildings.size(), 4u);
    try {
        build("<scene version=\"1\"><city file=\"../tests/data/osm/small-district.osm\"/></scene>");
        ADD_FAILURE() << "a city without rules was built";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("test.xml:1:32: the city names no <Rulefile>"), std::string::npos) << e.what();
    }
}

TEST(GenerateCity, StreetsJoinThePointsTheyName) {
    // Ids out of file order and with gaps: streets must not take them for positions.
    CityData data = parseCityData("<CityData><Points><Point id=\"30\" e=\"0\" n=\"0\"/><Point id=\"7\" e=\"50\" n=\"0\"/>"
                                  "<Point id=\"12\" e=\"50\" n=\"40\"/></Points><StreetNetwork><Streets>"
                                  "<Street id=\"0\" startPoint=\"7\" endPoint=\"12\"/></Streets></StreetNetwork></CityData>",
                                  "ids.xml", ".");
    StreetNetwork network = streetNetworkOf(data);
    ASSERT_EQ(network.streets.size(), 1u);
    Vec2f from = network.nodes[network.streets[0].from], to = network.nodes[network.streets[0].to];
    EXPECT_EQ(from.x, 50);
    EXPECT_EQ(from.y, 0);
    EXPECT_EQ(to.x, 50);
    EXPECT_EQ(to.y, 40);
}

TEST(GenerateCity, ErrorsAreAtTheirPlace) {
    auto errorOf = [](const std::string &xml) {
        try {
            build(xml);
        } catch (const InputError &e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(errorOf("<scene version=\"1\"><city file=\"nowhere.xml\"/></scene>").find("test.xml:1:32: cannot read the city file"),
              std::string::npos);
    EXPECT_NE(errorOf("<scene version=\"1\"><city file=\"../cities/bilke-listing-2-1.xml\" colour=\"red\"/></scene>")
                  .find("test.xml:1:"),
              std::string::npos);
}

}  // namespace
}  // namespace veduta
