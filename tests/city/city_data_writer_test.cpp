// Writing CityData files: what is written reads back as it was, a grown city with its lots
// included, in local metres and in map coordinates.
#include "city/city_data_writer.h"

#include <gtest/gtest.h>

#include "city/building_rules.h"
#include "city/generate_city.h"
#include "city/grown_city.h"
#include "geodesy/map_projection.h"
#include "streets/street_rule_file.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// A grid town with perimeter lots, as `veduta generate` writes it.
CityData grownTownWithLots() {
    CityGrowth growth;
    growth.radius = 200;
    growth.seed = 5;
    std::vector<std::string> warnings;
    CityData city = growCity(readStreetRuleFile(test::sourceFile("rules/streets/grid.txt")), growth, warnings);
    std::filesystem::path rules = test::sourceFile("rules/gruenderzeit/FacadeStructure.xml");
    city.ruleFiles = {rules};
    cutLots(city, BuildingRules(rules).rules.settings, 5, warnings);
    return city;
}

void expectSameOutline(const std::vector<Vec2f> &read, const std::vector<Vec2f> &written, double east = 0,
                       double north = 0, double tolerance = 0) {
    ASSERT_EQ(read.size(), written.size());
    for (size_t i = 0; i < read.size(); ++i) {
        EXPECT_NEAR(read[i].x - east, written[i].x, tolerance) << i;
        EXPECT_NEAR(read[i].y - north, written[i].y, tolerance) << i;
    }
}

TEST(CityDataWriter, AGrownTownWithItsLotsReadsBackAsItWas) {
    CityData city = grownTownWithLots();
    ASSERT_GT(city.blocks.size(), 5u);
    test::ScratchFolder folder("writer");
    std::string xml = cityDataXml(city, {{}, "made by a test"}, folder.path());
    CityData read = parseCityData(xml, "town.xml", folder.path());
    EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
    EXPECT_NE(xml.find("<!-- made by a test -->"), std::string::npos);

    ASSERT_GE(read.points.size(), city.points.size());
    for (size_t i = 0; i < city.points.size(); ++i) {
        EXPECT_EQ(read.points[i].id, city.points[i].id);
        // Written as the floats they are; read as double, they are those floats again.
        EXPECT_EQ(float(read.points[i].e), float(city.points[i].e));
        EXPECT_EQ(float(read.points[i].n), float(city.points[i].n));
    }
    ASSERT_EQ(read.streets.size(), city.streets.size());
    for (size_t i = 0; i < city.streets.size(); ++i) {
        EXPECT_EQ(read.streets[i].start, city.streets[i].start);
        EXPECT_EQ(read.streets[i].end, city.streets[i].end);
        EXPECT_EQ(read.streets[i].width, city.streets[i].width);
    }
    EXPECT_EQ(read.streetWidth, city.streetWidth);
    ASSERT_EQ(read.blocks.size(), city.blocks.size());
    size_t lots = 0;
    for (size_t b = 0; b < city.blocks.size(); ++b) {
        expectSameOutline(read.blocks[b].points, city.blocks[b].points);
        ASSERT_EQ(read.blocks[b].lots.size(), city.blocks[b].lots.size());
        for (size_t l = 0; l < city.blocks[b].lots.size(); ++l, ++lots) {
            expectSameOutline(read.blocks[b].lots[l].points, city.blocks[b].lots[l].points);
            EXPECT_EQ(read.blocks[b].lots[l].streetEdges, city.blocks[b].lots[l].streetEdges);
        }
    }
    EXPECT_GT(lots, 20u);
    ASSERT_EQ(read.ruleFiles.size(), 1u);
    EXPECT_TRUE(std::filesystem::equivalent(read.ruleFiles[0], city.ruleFiles[0]));
}

TEST(CityDataWriter, MapCoordinatesAreTheLocalOnesMovedByTheOffset) {
    CityData city = grownTownWithLots();
    MapOffset offset{487000, 5425000};
    Georeference utm{25832, offset.east, offset.north};
    MapProjection projection(crsByEpsg(25832), utm);
    CityData read = parseCityData(cityDataXml(city, {offset, ""}, "."), "town.xml", ".", &projection);
    ASSERT_EQ(read.blocks.size(), city.blocks.size());
    for (size_t i = 0; i < city.points.size(); ++i) {
        EXPECT_NEAR(read.points[i].e, city.points[i].e, 1e-4);
        EXPECT_NEAR(read.points[i].n, city.points[i].n, 1e-4);
    }
}

TEST(CityDataWriter, SettingsAndHeightsAreWritten) {
    CityData city;
    city.points = {{0, 0, 0, 2, {}}, {1, 30, 0, 2, {}}, {2, 30, 30, 2, {}}};
    city.streets = {{0, 0, 1, 6.5f, {}}};
    CityBlock block;
    block.points = {{0, 0}, {30, 0}, {30, 30}};
    block.base = 2;
    block.settings["FloorHeight"] = settingValue("3.5", {});
    city.blocks.push_back(block);
    city.settings["LotSubdivision"] = settingValue("schrader", {});
    city.settings["BuildingHeight"] = settingValue("18", {});
    CityData read = parseCityData(cityDataXml(city, {}, "."), "city.xml", ".");
    EXPECT_EQ(read.points[2].u, 2);
    EXPECT_EQ(read.streets[0].width, 6.5f);
    EXPECT_EQ(read.settings.at("LotSubdivision").text, "schrader");
    EXPECT_EQ(read.settings.at("BuildingHeight").number, 18.0f);
    EXPECT_EQ(read.blocks[0].settings.at("FloorHeight").number, 3.5f);
    EXPECT_EQ(read.blocks[0].base, 2);
}

TEST(CityDataWriter, TheFileIsWrittenWholeOrNotAtAll) {
    test::ScratchFolder folder("writer-file");
    CityData city = grownTownWithLots();
    std::filesystem::path file = folder.path() / "town.xml";
    writeCityData(city, {}, file);
    CityData read = readCityData(file);
    EXPECT_EQ(read.blocks.size(), city.blocks.size());
    std::filesystem::path blocked = folder.write("plain-file", "") / "town.xml";
    EXPECT_THROW(writeCityData(city, {}, blocked), std::exception);
}

}  // namespace
}  // namespace veduta
