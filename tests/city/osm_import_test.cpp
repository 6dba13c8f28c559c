// The OSM import: tests/data/osm/small-district.osm (two residential streets crossing, a footway,
// a pedestrian street, a residential area, five buildings near Leipzig) and files that are
// partly or wholly unusable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <GeographicLib/Geodesic.hpp>

#include "city/footprint.h"
#include "city/osm_import.h"
#include "input_error.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

const std::filesystem::path kOsmData = test::testData() / "osm";

CityData smallDistrict(const OsmImportOptions &options = {}) {
    return importOsm(kOsmData / "small-district.osm", options);
}

// What came from one way: its FileLoc reads "file: way <id>".
bool fromWay(const FileLoc &loc, int way) { return loc.file.ends_with(fmt::format(": way {}", way)); }

std::vector<CityStreet> streetsOf(const CityData &city, int way) {
    std::vector<CityStreet> streets;
    std::copy_if(city.streets.begin(), city.streets.end(), std::back_inserter(streets),
                 [&](const CityStreet &s) { return fromWay(s.loc, way); });
    return streets;
}

const CityLot &lotOf(const CityData &city, int way) {
    for (const CityBlock &block : city.blocks)
        for (const CityLot &lot : block.lots)
            if (fromWay(lot.loc, way)) return lot;
    throw std::runtime_error(fmt::format("no lot from way {}", way));
}

std::string setting(const CityLot &lot, const std::string &name) {
    auto it = lot.settings.find(name);
    return it == lot.settings.end() ? "(unset)" : it->second.text;
}

bool hasWarning(const CityData &city, const std::string &text) {
    return std::any_of(city.warnings.begin(), city.warnings.end(),
                       [&](const std::string &w) { return w.find(text) != std::string::npos; });
}

std::string errorOf(const std::filesystem::path &file) {
    return test::inputErrorOf([&] { importOsm(file, {}); });
}

TEST(OsmImport, HighwaysBecomeStreetsOfTheirWidth) {
    CityData city = smallDistrict();
    EXPECT_EQ(city.streets.size(), 6u);
    std::vector<CityStreet> ostweg = streetsOf(city, 2001), nord = streetsOf(city, 2002);
    ASSERT_EQ(ostweg.size(), 2u);  // three nodes: two streets
    ASSERT_EQ(nord.size(), 2u);
    for (const CityStreet &s : ostweg) EXPECT_EQ(s.width, 6.0f);  // highway=residential
    for (const CityStreet &s : nord) EXPECT_EQ(s.width, 7.5f);    // width="7.5 m"
    ASSERT_EQ(streetsOf(city, 2003).size(), 1u);
    EXPECT_EQ(streetsOf(city, 2003)[0].width, 2.0f);  // highway=footway
    ASSERT_EQ(streetsOf(city, 2004).size(), 1u);
    EXPECT_FALSE(streetsOf(city, 2004)[0].width.has_value());  // pedestrian: the network's width
    EXPECT_TRUE(streetsOf(city, 2005).empty());                // highway=proposed is not there yet
    for (size_t i = 0; i < city.streets.size(); ++i) EXPECT_EQ(city.streets[i].id, i);
}

TEST(OsmImport, OptionsGiveTheNetworkWidthAndTheRuleFiles) {
    OsmImportOptions options;
    options.defaultStreetWidth = 3.5f;
    options.ruleFiles = {"rules/a.xml", "rules/b.xml"};
    CityData city = smallDistrict(options);
    EXPECT_EQ(city.streetWidth, 3.5f);
    EXPECT_EQ(city.ruleFiles, options.ruleFiles);
}

TEST(OsmImport, StreetsShareTheirPointAtTheCrossing) {
    CityData city = smallDistrict();
    // Ostweg's three nodes, Nordstraße's two others, the footway's two and the pedestrian street's
    // far end: its first node lies 7 mm from the footway's end and is the same point.
    ASSERT_EQ(city.points.size(), 8u);
    std::vector<CityStreet> ostweg = streetsOf(city, 2001), nord = streetsOf(city, 2002);
    uint32_t crossing = ostweg[0].end;
    EXPECT_EQ(ostweg[1].start, crossing);
    EXPECT_EQ(nord[0].end, crossing);
    EXPECT_EQ(nord[1].start, crossing);
    EXPECT_EQ(streetsOf(city, 2004)[0].start, streetsOf(city, 2003)[0].end);
    // The crossing is the centre of the data's bounding box, the default origin.
    EXPECT_NEAR(city.points[crossing].e, 0, 1e-6);
    EXPECT_NEAR(city.points[crossing].n, 0, 1e-6);
    for (size_t i = 0; i < city.points.size(); ++i) {
        EXPECT_EQ(city.points[i].id, i);
        EXPECT_EQ(city.points[i].u, 0);
    }
}

TEST(OsmImport, TheLocalFrameKeepsGeodesicDistances) {
    CityData city = smallDistrict();
    // Ostweg's and Nordstraße's nodes as the file gives them, in the order they become points.
    const GeographicPoint nodes[] = {
        {51.33, 12.3685623}, {51.33, 12.37}, {51.33, 12.3714377}, {51.3291011, 12.37}, {51.3308989, 12.37}};
    const GeographicLib::Geodesic &wgs84 = GeographicLib::Geodesic::WGS84();
    for (size_t i = 0; i < std::size(nodes); ++i)
        for (size_t j = i + 1; j < std::size(nodes); ++j) {
            double geodesic = 0;
            wgs84.Inverse(nodes[i].latitude, nodes[i].longitude, nodes[j].latitude, nodes[j].longitude, geodesic);
            const CityPoint &a = city.points[i], &b = city.points[j];
            EXPECT_NEAR(std::hypot(b.e - a.e, b.n - a.n), geodesic, 0.01) << i << " " << j;
        }
}

TEST(OsmImport, AGivenOriginIsThePointAtZero) {
    OsmImportOptions options;
    options.origin = GeographicPoint{51.33, 12.3685623};  // Ostweg's west end
    CityData city = smallDistrict(options);
    EXPECT_NEAR(city.points[0].e, 0, 1e-6);
    EXPECT_NEAR(city.points[0].n, 0, 1e-6);
    double geodesic = 0;
    GeographicLib::Geodesic::WGS84().Inverse(51.33, 12.3685623, 51.33, 12.37, geodesic);
    EXPECT_NEAR(city.points[1].e, geodesic, 0.01);  // the crossing, east along the parallel
    EXPECT_NEAR(city.points[1].n, 0, 0.01);
}

TEST(OsmImport, TheResidentialAreaIsACounterClockwiseBlock) {
    CityData city = smallDistrict();
    ASSERT_EQ(city.blocks.size(), 2u);
    const CityBlock &block = city.blocks[0];
    EXPECT_TRUE(fromWay(block.loc, 2010));
    ASSERT_EQ(block.points.size(), 4u);                           // the closing node is not repeated
    EXPECT_TRUE(isCounterClockwise(block.points));                // the file draws it clockwise
    EXPECT_TRUE(city.warnings.empty()) << city.warnings.front();  // OSM has no orientation rule
}

TEST(OsmImport, BuildingsAreLotsInsideTheirBlock) {
    CityData city = smallDistrict();
    ASSERT_EQ(city.blocks.size(), 2u);
    const CityBlock &block = city.blocks[0];
    ASSERT_EQ(block.lots.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(fromWay(block.lots[i].loc, 2020 + i));
    for (const CityLot &lot : block.lots) {
        EXPECT_TRUE(liesInside(lot.points, block.points));
        EXPECT_TRUE(isCounterClockwise(lot.points));  // way 2020 is drawn clockwise
        EXPECT_EQ(lot.streetEdges.size(), lot.points.size());
    }
    // The house outside the residential area stands in a block of its own, its outline.
    const CityBlock &own = city.blocks[1];
    ASSERT_EQ(own.lots.size(), 1u);
    EXPECT_TRUE(fromWay(own.lots[0].loc, 2024));
    ASSERT_EQ(own.points.size(), own.lots[0].points.size());
    for (size_t i = 0; i < own.points.size(); ++i) {
        EXPECT_EQ(own.points[i].x, own.lots[0].points[i].x);
        EXPECT_EQ(own.points[i].y, own.lots[0].points[i].y);
    }
}

TEST(OsmImport, EdgesNearAStreetAreStreetEdges) {
    CityData city = smallDistrict();
    // The corner house (6…20 m east and north of the crossing) faces Ostweg with its south edge
    // and Nordstraße with its west edge; both lie 6 m from the centrelines.
    const CityLot &corner = lotOf(city, 2020);
    size_t n = corner.points.size();
    ASSERT_EQ(n, 4u);
    for (size_t i = 0; i < n; ++i) {
        Vec2f a = corner.points[i], b = corner.points[(i + 1) % n];
        bool south = a.y < 7 && b.y < 7, west = a.x < 7 && b.x < 7;
        EXPECT_EQ(corner.streetEdges[i], south || west) << "edge " << i;
    }
    // The house in the middle of the block faces no street.
    const CityLot &inner = lotOf(city, 2023);
    EXPECT_EQ(std::count(inner.streetEdges.begin(), inner.streetEdges.end(), true), 0);
    const CityLot &alongOstweg = lotOf(city, 2021);
    EXPECT_EQ(std::count(alongOstweg.streetEdges.begin(), alongOstweg.streetEdges.end(), true), 1);
}

TEST(OsmImport, BuildingTagsBecomeSettings) {
    CityData city = smallDistrict();
    const CityLot &corner = lotOf(city, 2020);                      // height 18, roof:height 5, gabled
    EXPECT_EQ(corner.settings.at("BuildingHeight").number, 13.0f);  // the walls: height less the roof
    EXPECT_EQ(corner.settings.at("RoofHeight").number, 5.0f);
    EXPECT_EQ(setting(corner, "RoofType"), "Gable");
    EXPECT_EQ(setting(corner, "osm:name"), "Eckhaus");
    EXPECT_EQ(setting(corner, "osm:building"), "apartments");
    EXPECT_EQ(setting(corner, "osm:height"), "(unset)");  // mapped tags are not kept twice
    EXPECT_EQ(setting(corner, "osm:roof:shape"), "(unset)");
    EXPECT_NE(corner.settings.at("BuildingHeight").loc.toString().find("small-district.osm: way 2020"),
              std::string::npos);

    const CityLot &levels = lotOf(city, 2021);                      // building:levels 4, hipped
    EXPECT_EQ(levels.settings.at("BuildingHeight").number, 12.0f);  // 4 floors of 3 m
    EXPECT_EQ(setting(levels, "RoofType"), "Hip");
    EXPECT_EQ(setting(levels, "RoofHeight"), "(unset)");

    const CityLot &both = lotOf(city, 2022);  // height "15 m" and building:levels 5: height wins
    EXPECT_EQ(both.settings.at("BuildingHeight").number, 15.0f);
    EXPECT_EQ(setting(both, "osm:building:levels"), "5");
    EXPECT_EQ(both.settings.at("osm:building:levels").number, 5.0f);
    EXPECT_EQ(setting(both, "RoofType"), "Mansard");

    EXPECT_EQ(setting(lotOf(city, 2023), "RoofType"), "Flat");
    EXPECT_EQ(setting(lotOf(city, 2023), "osm:name"),
              "Garagen \"Am Hof\", 2\\3");  // GDAL escapes quotes and backslashes
    EXPECT_EQ(setting(lotOf(city, 2024), "RoofType"), "Shed");
    EXPECT_EQ(setting(lotOf(city, 2024), "BuildingHeight"), "(unset)");  // no height: the defaults'
}

TEST(OsmImport, UnusableWaysAreSkippedWithAWarning) {
    CityData city = importOsm(kOsmData / "bad-ways.osm", {});
    std::string file = (kOsmData / "bad-ways.osm").string();
    for (const char *warning :
         {": way 2001: width 'wide' is not a length in metres; the street takes highway=tertiary's width",
          ": relation 3001: blocks have no holes: the residential area's 1 inner ring(s) are ignored",
          ": way 2020: the outline crosses or touches itself, or has no area; it is skipped",
          ": way 2021: an outline of 2 points is no polygon; it is skipped",
          ": way 2022: height 'tall' is not a length in metres; kept as osm:height",
          ": way 2022: roof:shape 'onion' has no RoofType; kept as osm:roof:shape"})
        EXPECT_TRUE(hasWarning(city, file + warning)) << warning;
    EXPECT_EQ(city.warnings.size(), 6u);
    ASSERT_EQ(city.streets.size(), 1u);
    EXPECT_EQ(city.streets[0].width, 8.0f);
    ASSERT_EQ(city.blocks.size(), 1u);
    ASSERT_EQ(city.blocks[0].lots.size(), 1u);
    const CityLot &lot = city.blocks[0].lots[0];
    EXPECT_EQ(setting(lot, "osm:height"), "tall");
    EXPECT_EQ(setting(lot, "osm:roof:shape"), "onion");
    EXPECT_EQ(setting(lot, "BuildingHeight"), "(unset)");
}

// Single precision builds a city; far from the origin its streets and Booleans fall apart.
TEST(OsmImport, AWayReachingBeyondACitysReachIsSkipped) {
    test::ScratchFolder folder("osm_reach");
    auto file = folder.write("far.osm", R"(<?xml version="1.0"?>
<osm version="0.6">
  <node id="1" lat="49.4400" lon="7.7600"/>
  <node id="2" lat="49.4410" lon="7.7620"/>
  <node id="3" lat="49.4420" lon="9.5000"/>
  <way id="10"><nd ref="1"/><nd ref="2"/><tag k="highway" v="residential"/></way>
  <way id="11"><nd ref="2"/><nd ref="3"/><tag k="highway" v="residential"/></way>
</osm>
)");
    OsmImportOptions options;
    options.origin = GeographicPoint{49.44, 7.76};
    CityData city = importOsm(file, options);
    ASSERT_EQ(city.warnings.size(), 1u);
    EXPECT_EQ(city.warnings[0],
              file.string() +
                  ": way 11: its node at 49.4420000 9.5000000 lies 126 km from the data's origin, "
                  "beyond the 100 km a city reaches; it is skipped");
    ASSERT_EQ(city.streets.size(), 1u);
    EXPECT_TRUE(fromWay(city.streets[0].loc, 10));
}

TEST(OsmImport, AFileGdalCannotReadIsAnInputErrorNamingIt) {
    // GDAL's "… at line 8, column 4" becomes the place.
    EXPECT_EQ(errorOf(kOsmData / "broken.osm"),
              (kOsmData / "broken.osm").string() + ":8:4: XML parsing of OSM file failed: unclosed token");
    EXPECT_EQ(errorOf(kOsmData / "../tetra.obj"),
              (kOsmData / "../tetra.obj").string() +
                  ": GDAL cannot read this as an OpenStreetMap XML file (GDAL finds no <osm> element at its start)");
    test::ScratchFolder folder("osm_errors");
    auto twice = folder.write("twice.osm", R"(<?xml version="1.0"?>
<osm version="0.6">
  <node id="1" lat="49.44" lon="7.76"/>
  <node id="1" lat="49.45" lon="7.77"/>
</osm>
)");
    EXPECT_EQ(errorOf(twice).rfind(twice.string() + ": two nodes have the id 1 (GDAL: Failed inserting node 1: ", 0),
              0u)
        << errorOf(twice);
    std::string missing = errorOf(kOsmData / "no-such-file.osm");
    EXPECT_NE(missing.find("no-such-file.osm: cannot open file"), std::string::npos) << missing;
}

}  // namespace
}  // namespace veduta
