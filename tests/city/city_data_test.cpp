// Bilke's CityData files: the completed Listing 2.1, settings precedence (T6), computed
// street edges, and every error at its place.
#include <gtest/gtest.h>

#include <filesystem>

#include "city/city_data.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

CityData listing() { return readCityData(test::sourceFile("cities/bilke-listing-2-1.xml")); }

std::string errorOf(const std::string &xml) {
    return test::inputErrorOf([&] { parseCityData(xml, "city.xml", "."); });
}

// A city of four points and one block around them; `block` and `lots` go inside <Block>.
std::string city(const std::string &points, const std::string &block) {
    return "<CityData>\n<Points>\n" + points + "</Points>\n<Blocks><Block>\n" + block +
        "</Block></Blocks>\n</CityData>";
}

const char *kSquare =
    "<Point id=\"0\" e=\"0\" n=\"0\"/><Point id=\"1\" e=\"40\" n=\"0\"/>\n"
    "<Point id=\"2\" e=\"40\" n=\"40\"/><Point id=\"3\" e=\"0\" n=\"40\"/>\n";
const char *kSquareBlock = "<Points><Point id=\"0\"/><Point id=\"1\"/><Point id=\"2\"/><Point id=\"3\"/></Points>\n";

TEST(CityData, TheCompletedListingTwoOneReads) {
    CityData data = listing();
    EXPECT_EQ(data.points.size(), 10u);
    ASSERT_EQ(data.streets.size(), 8u);
    EXPECT_EQ(data.streets[1].width, 8.0f);
    EXPECT_FALSE(data.streets[0].width.has_value());
    EXPECT_EQ(data.streetWidth, 5.0f);
    ASSERT_EQ(data.blocks.size(), 2u);
    EXPECT_TRUE(data.blocks[0].lots.empty());
    ASSERT_EQ(data.blocks[1].lots.size(), 1u);
    // The lot 9 8 5 4 is clockwise too: read backwards, 4 5 8 9, its street flags on their edges.
    const CityLot &lot = data.blocks[1].lots[0];
    EXPECT_EQ(lot.streetEdges, (std::vector<bool>{true, false, false, true}));
    EXPECT_EQ(lot.points.front().x, 70);
    EXPECT_EQ(lot.points.front().y, 0);
    ASSERT_EQ(data.ruleFiles.size(), 1u);
    EXPECT_TRUE(std::filesystem::exists(data.ruleFiles[0])) << data.ruleFiles[0];
    // The printed block is counter-clockwise in veduta's frame (see the file's note) and kept as
    // it is; the completed one and its lot are clockwise, turned round with a warning each.
    ASSERT_EQ(data.warnings.size(), 2u);
    EXPECT_NE(data.warnings[0].find("bilke-listing-2-1.xml:63:7: the block runs clockwise"), std::string::npos)
        << data.warnings[0];
    EXPECT_NE(data.warnings[1].find("bilke-listing-2-1.xml:71:11: the footprint runs clockwise"), std::string::npos)
        << data.warnings[1];
    const std::vector<Vec2f> &printed = data.blocks[0].points;
    EXPECT_EQ(printed.front().x, 20);  // 3 2 1 0 as printed
    EXPECT_EQ(printed.front().y, -30);
    const std::vector<Vec2f> &completed = data.blocks[1].points;
    EXPECT_EQ(completed.front().x, 70);  // 7 6 5 4 read backwards: 4 5 6 7
    EXPECT_EQ(completed.front().y, 0);
}

TEST(CityData, T6SettingsPrecedenceLotBlockCityRuleFileDefaults) {
    CityData data = listing();
    SettingsMap ruleFile{{"FloorHeight", settingValue("3.2", {})}, {"BuildingHeight", settingValue("99", {})}};
    SettingsStack lot = settingsFor(data, data.blocks[1], &data.blocks[1].lots[0], ruleFile);
    SettingsStack blockOne = settingsFor(data, data.blocks[0], nullptr, ruleFile);
    EXPECT_EQ(lot.number("BuildingHeight"), 16.0f);       // the lot's own
    EXPECT_EQ(blockOne.number("BuildingHeight"), 12.0f);  // the city's, over the rule file's
    EXPECT_EQ(blockOne.number("BuildingHeightVar"), 2.0f);
    EXPECT_EQ(blockOne.number("LODLevel"), 1.0f);     // the block's
    EXPECT_EQ(lot.number("LODLevel"), std::nullopt);  // another block's is not the lot's
    EXPECT_EQ(lot.number("FloorHeight"), 3.2f);       // the rule file's, over the default 3
    EXPECT_EQ(lot.number("RoofHeight"), 4.0f);        // the built-in default
}

TEST(CityData, ALotWithoutStreetFlagsGetsTheEdgesAlongItsStreets) {
    std::string xml = "<CityData>\n<Points>\n" + std::string(kSquare) +
        "<Point id=\"4\" e=\"0\" n=\"12\"/><Point id=\"5\" e=\"40\" n=\"12\"/>\n</Points>\n"
        "<StreetNetwork><Streets><Street id=\"0\" startPoint=\"0\" endPoint=\"1\"/></Streets>"
        "<Width>6</Width></StreetNetwork>\n<Blocks><Block>\n" +
        kSquareBlock +
        "<Lots><Lot><Points><Point id=\"0\"/><Point id=\"1\"/><Point id=\"5\"/><Point id=\"4\"/></Points>"
        "</Lot></Lots>\n</Block></Blocks>\n</CityData>";
    CityData data = parseCityData(xml, "city.xml", ".");
    EXPECT_EQ(data.blocks[0].lots[0].streetEdges, (std::vector<bool>{true, false, false, false}));
}

TEST(CityData, ErrorsAreAtTheirPlace) {
    auto expectError = [](const std::string &xml, const std::string &expected) {
        std::string error = errorOf(xml);
        EXPECT_NE(error.find(expected), std::string::npos) << "got: " << error << "\nexpected: " << expected;
    };
    expectError(city("<Point id=\"0\" e=\"0\" n=\"0\"/><Point id=\"0\" e=\"1\" n=\"0\"/>\n", ""),
                "city.xml:3:39: point id 0 is already used at city.xml:3:1");
    expectError(city(kSquare, "<Points><Point id=\"0\"/><Point id=\"1\"/><Point id=\"7\"/></Points>\n"),
                "city.xml:7:50: there is no point with id 7");
    expectError(
        city(kSquare, "<Points><Point id=\"0\"/><Point id=\"2\"/><Point id=\"1\"/><Point id=\"3\"/></Points>\n"),
        "city.xml:7:1: the block's outline crosses or touches itself");
    expectError(city(kSquare, "<Points><Point id=\"0\"/><Point id=\"1\"/></Points>\n"),
                "city.xml:7:1: a block needs at least 3 points, not 2");
    // Found by fuzz/city_data: a point 7e17 m out broke the street Booleans.
    expectError(city("<Point id=\"0\" e=\"666666666666666650\" n=\"0\"/>\n", ""),
                "city.xml:3:18: the point lies at (6.66667e+17, 0, 0) m from 0 0 (map coordinates need the scene's "
                "<georeference> to be placed); a city's points must lie within "
                "100 km of it (and heights within 100 km)");
    expectError(city("<Point id=\"0\" e=\"0\" n=\"-100001\"/>\n", ""),
                "city.xml:3:24: the point lies at (0, -100001, 0) m");
    expectError(city("<Point id=\"0\" e=\"0\" n=\"0\" u=\"2e5\"/>\n", ""),
                "city.xml:3:30: the point lies at (0, 0, 200000) m");
    expectError(city("<Point id=\"0\" e=\"0\" n=\"0\"/><Point id=\"1\" e=\"9\" n=\"0\" u=\"2\"/>"
                     "<Point id=\"2\" e=\"9\" n=\"9\"/>\n",
                     "<Points><Point id=\"0\"/><Point id=\"1\"/><Point id=\"2\"/></Points>\n"),
                "city.xml:6:1: the points of a block must share one height u; they have 0 and 2");
    expectError(
        city(std::string(kSquare) + "<Point id=\"4\" e=\"50\" n=\"0\"/><Point id=\"5\" e=\"50\" n=\"10\"/>\n",
             std::string(kSquareBlock) +
                 "<Lots><Lot><Points><Point id=\"0\"/><Point id=\"4\"/><Point id=\"5\"/></Points></Lot></Lots>\n"),
        "city.xml:9:12: the lot's point (50 0) lies outside its block");
    // A concave block (a U open to the north): a lot whose corners lie in it but whose edge
    // crosses the notch.
    expectError(
        city("<Point id=\"0\" e=\"0\" n=\"0\"/><Point id=\"1\" e=\"30\" n=\"0\"/><Point id=\"2\" e=\"30\" n=\"30\"/>"
             "<Point id=\"3\" e=\"20\" n=\"30\"/><Point id=\"4\" e=\"20\" n=\"10\"/><Point id=\"5\" e=\"10\" n=\"10\"/>"
             "<Point id=\"6\" e=\"10\" n=\"30\"/><Point id=\"7\" e=\"0\" n=\"30\"/>\n",
             "<Points><Point id=\"0\"/><Point id=\"1\"/><Point id=\"2\"/><Point id=\"3\"/><Point id=\"4\"/>"
             "<Point id=\"5\"/><Point id=\"6\"/><Point id=\"7\"/></Points>\n"
             "<Lots><Lot><Points><Point id=\"7\"/><Point id=\"0\"/><Point id=\"1\"/><Point "
             "id=\"2\"/></Points></Lot></Lots>\n"),
        "city.xml:7:12: the lot's edge from (30 30) to (0 30) leaves its block");
    expectError(city(kSquare,
                     std::string(kSquareBlock) +
                         "<Lots><Lot><Points><Point id=\"0\"/><Point id=\"1\"/>"
                         "<Point id=\"0\"/></Points></Lot></Lots>\n"),
                "city.xml:8:12: footprint point 3 repeats point 1");  // a lot of no area
    auto withStreets = [](const std::string &streets) {
        return std::string("<CityData>\n<Points>\n") + kSquare + "</Points>\n<StreetNetwork><Streets>\n" + streets +
            "</Streets></StreetNetwork>\n</CityData>";
    };
    expectError(
        withStreets(
            "<Street id=\"4\" startPoint=\"0\" endPoint=\"1\"/>\n<Street id=\"4\" startPoint=\"1\" endPoint=\"2\"/>\n"),
        "city.xml:8:13: street id 4 is already used at city.xml:7:1");
    expectError(withStreets("<Street id=\"0\" startPoint=\"2\" endPoint=\"2\"/>\n"),
                "city.xml:7:1: the street starts and ends at point 2");
    expectError(city(kSquare, std::string(kSquareBlock) + "<Houses/>\n"),
                "city.xml:8:1: unknown element <Houses> in <Block>");
    expectError("<City/>", "city.xml:1:1: the root element is <City>, expected <CityData>");
    expectError("<CityData><Points><Point id=\"0\" e=\"x\" n=\"0\"/></Points></CityData>", "city.xml:1:");
}

}  // namespace
}  // namespace veduta
