// Cities in a georeferenced scene's frame (issue 16): CityData points in the <city>'s crs (by
// default the scene's) and OpenStreetMap's WGS 84 nodes go through the one route of
// geo/map_projection.h, so the same streets given either way land on the same render points.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "city/city_data.h"
#include "city/osm_import.h"
#include "geodesy/map_projection.h"
#include "input_error.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// A crossing of two streets and a house beside it, in Kassel: WGS 84 latitude and longitude.
struct Node {
    int id;
    double latitude, longitude;
};
const Node kStreetNodes[] = {
    {1, 51.31, 9.488}, {2, 51.31, 9.49}, {3, 51.31, 9.492}, {4, 51.309, 9.49}, {5, 51.311, 9.49}};
const Node kHouseNodes[] = {{6, 51.3102, 9.4903}, {7, 51.3102, 9.4906}, {8, 51.3104, 9.4906}, {9, 51.3104, 9.4903}};
const std::pair<int, int> kStreets[] = {{1, 2}, {2, 3}, {4, 2}, {2, 5}};

std::vector<Node> allNodes() {
    std::vector<Node> nodes(std::begin(kStreetNodes), std::end(kStreetNodes));
    nodes.insert(nodes.end(), std::begin(kHouseNodes), std::end(kHouseNodes));
    return nodes;
}

CrsCoordinate inCrs(const Node &node, int epsg) {
    return convert(crsByEpsg(4326), crsByEpsg(epsg), {node.longitude, node.latitude, 0});
}

// The scene origin: a few hundred metres from the crossing, in UTM 32.
Georeference utmScene() {
    CrsCoordinate crossing = inCrs(kStreetNodes[1], 25832);
    return {25832, std::round(crossing.x / 100) * 100 + 300, std::round(crossing.y / 100) * 100 - 200};
}

std::string osmXml() {
    std::string nodes, ways;
    for (const Node &n : allNodes())
        nodes += fmt::format("<node id=\"{}\" version=\"1\" lat=\"{:.7f}\" lon=\"{:.7f}\"/>\n", n.id, n.latitude,
                             n.longitude);
    ways +=
        "<way id=\"100\" version=\"1\"><nd ref=\"1\"/><nd ref=\"2\"/><nd ref=\"3\"/>"
        "<tag k=\"highway\" v=\"residential\"/></way>\n";
    ways +=
        "<way id=\"101\" version=\"1\"><nd ref=\"4\"/><nd ref=\"2\"/><nd ref=\"5\"/>"
        "<tag k=\"highway\" v=\"residential\"/></way>\n";
    ways +=
        "<way id=\"102\" version=\"1\"><nd ref=\"6\"/><nd ref=\"7\"/><nd ref=\"8\"/><nd ref=\"9\"/><nd ref=\"6\"/>"
        "<tag k=\"building\" v=\"yes\"/></way>\n";
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<osm version=\"0.6\" generator=\"test\">\n" + nodes + ways +
        "</osm>\n";
}

// The same streets and house as CityData with coordinates in `epsg`.
std::string cityDataXml(int epsg) {
    std::string points, streets;
    for (const Node &n : allNodes()) {
        CrsCoordinate c = inCrs(n, epsg);
        points += fmt::format("<Point id=\"{}\" e=\"{:.4f}\" n=\"{:.4f}\"/>", n.id, c.x, c.y);
    }
    int id = 1;
    for (auto [from, to] : kStreets)
        streets += fmt::format("<Street id=\"{}\" startPoint=\"{}\" endPoint=\"{}\"/>", id++, from, to);
    std::string outline = "<Points><Point id=\"6\"/><Point id=\"7\"/><Point id=\"8\"/><Point id=\"9\"/></Points>";
    return fmt::format(
        "<CityData><Points>{}</Points><StreetNetwork><Streets>{}</Streets></StreetNetwork>"
        "<Blocks><Block>{}<Lots><Lot>{}</Lot></Lots></Block></Blocks></CityData>",
        points, streets, outline, outline);
}

class CityMapFrame : public testing::Test {
  protected:
    std::filesystem::path write(const std::string &name, const std::string &text) const {
        return folder_.write(name, text);
    }
    static std::string errorOf(const std::string &xml) { return test::sceneErrorOf(xml); }

    test::ScratchFolder folder_{"city_map_frame"};
    const std::filesystem::path &dir_ = folder_.path();
};

// Every point of `a` has one of `b` within `tolerance` metres.
void expectSamePoints(const std::vector<Vec2f> &a, const std::vector<Vec2f> &b, double tolerance) {
    ASSERT_EQ(a.size(), b.size());
    for (Vec2f p : a) {
        double nearest = INFINITY;
        for (Vec2f q : b) nearest = std::min(nearest, std::hypot(double(p.x) - q.x, double(p.y) - q.y));
        EXPECT_LT(nearest, tolerance) << p.x << " " << p.y;
    }
}

std::vector<Vec2f> streetNodes(const CityData &city) {
    std::vector<Vec2f> nodes;
    for (const CityPoint &p : city.points) nodes.push_back({float(p.e), float(p.n)});
    return nodes;
}

TEST_F(CityMapFrame, OsmAndCityDataInAnotherCrsGiveTheSamePointsWithinACentimetre) {
    OsmImportOptions options;
    options.georeference = utmScene();
    CityData osm = importOsm(write("crossing.osm", osmXml()), options);
    MapProjection gaussKrueger(crsByEpsg(31467), utmScene());
    CityData city = parseCityData(cityDataXml(31467), "crossing.xml", dir_, &gaussKrueger);

    ASSERT_EQ(osm.points.size(), 5u);  // the crossing's node is one point of both streets
    EXPECT_EQ(osm.streets.size(), city.streets.size());
    std::vector<Vec2f> cityStreetNodes = streetNodes(city);
    cityStreetNodes.resize(5);  // the house's points come after
    expectSamePoints(streetNodes(osm), cityStreetNodes, 0.01);
    ASSERT_EQ(osm.blocks.size(), 1u);
    ASSERT_EQ(city.blocks.size(), 1u);
    ASSERT_EQ(osm.blocks[0].lots.size(), 1u);
    ASSERT_EQ(city.blocks[0].lots.size(), 1u);
    expectSamePoints(osm.blocks[0].lots[0].points, city.blocks[0].lots[0].points, 0.01);
    expectSamePoints(osm.blocks[0].points, city.blocks[0].points, 0.01);
}

// With a georeference OSM lies on the scene's grid, as the landscape: UTM less the origin,
// not the tangent plane at the data (which is turned by the meridian convergence, 0.4° here).
TEST_F(CityMapFrame, OsmWithAGeoreferenceIsOnTheScenesGrid) {
    OsmImportOptions options;
    options.georeference = utmScene();
    CityData osm = importOsm(write("crossing.osm", osmXml()), options);
    for (size_t i = 0; i < 5; ++i) {
        CrsCoordinate utm = inCrs(kStreetNodes[i], 25832);
        const CityPoint &p = osm.points[i];
        EXPECT_NEAR(p.e, utm.x - options.georeference->originEasting, 1e-3) << i;
        EXPECT_NEAR(p.n, utm.y - options.georeference->originNorthing, 1e-3) << i;
    }
    // The street from node 4 to 5 runs along the meridian: on the tangent plane due north, on
    // the UTM grid turned by the convergence east of 9° E.
    CityData tangent = importOsm(write("crossing.osm", osmXml()), {});
    double gridTurn = std::atan2(osm.points[4].e - osm.points[3].e, osm.points[4].n - osm.points[3].n);
    double tangentTurn =
        std::atan2(tangent.points[4].e - tangent.points[3].e, tangent.points[4].n - tangent.points[3].n);
    EXPECT_NEAR(tangentTurn, 0, 1e-6);
    EXPECT_GT(std::abs(gridTurn), 0.005);
}

TEST_F(CityMapFrame, CityDataTakesTheScenesCrsByDefault) {
    Georeference scene = utmScene();
    std::string xml = fmt::format(
        "<CityData><Points><Point id=\"1\" e=\"{:.3f}\" n=\"{:.3f}\" u=\"5\"/></Points>"
        "</CityData>",
        scene.originEasting + 12.25, scene.originNorthing - 3.5);
    MapProjection own(crsByEpsg(scene.epsg), scene);
    CityData city = parseCityData(xml, "city.xml", dir_, &own);
    ASSERT_EQ(city.points.size(), 1u);
    EXPECT_NEAR(city.points[0].e, 12.25, 1e-9);
    EXPECT_NEAR(city.points[0].n, -3.5, 1e-9);
    EXPECT_EQ(city.points[0].u, 5);
    // Without a projection the same numbers would be local metres as they stand, hundreds of
    // kilometres out, where single precision cannot build a city.
    EXPECT_EQ(
        test::inputErrorOf([&] { parseCityData(xml, "city.xml", dir_); })
            .rfind("city.xml:1:36: the point lies at (534512, 5.6842e+06, 5) m from 0 0 (map coordinates need the "
                   "scene's <georeference> to be placed); a city's points must lie within 100 km of it",
                   0),
        0u);
}

TEST_F(CityMapFrame, Errors) {
    std::filesystem::path city = write("crossing.xml", cityDataXml(31467));
    std::filesystem::path osm = write("crossing.osm", osmXml());
    Georeference g = utmScene();
    std::string georeference =
        fmt::format("<georeference crs=\"EPSG:25832\" origin=\"{} {}\"/>", g.originEasting, g.originNorthing);
    auto cityScene = [&](const std::filesystem::path &file, const std::string &attributes, bool georeferenced) {
        return fmt::format("<scene version=\"1\">{}<city file=\"{}\" {}/></scene>", georeferenced ? georeference : "",
                           file.string(), attributes);
    };
    // crs's value starts at column 19 (<scene …>) + 12 (<city file=") + the path + 2 + 5 (crs=").
    EXPECT_EQ(errorOf(cityScene(city, "crs=\"EPSG:31467\"", false)),
              fmt::format("test.xml:1:{}: a city in map coordinates (crs) needs the scene's <georeference "
                          "crs=\"EPSG:…\" origin=\"E N\"> to be placed",
                          city.string().size() + 39));
    EXPECT_NE(errorOf(cityScene(city, "crs=\"EPSG:3857\"", true)).find("EPSG:3857 is not supported"),
              std::string::npos);
    EXPECT_NE(errorOf(cityScene(osm, "crs=\"EPSG:4326\"", true))
                  .find("OpenStreetMap data is WGS 84 longitude and latitude; leave out crs"),
              std::string::npos);
    // Gauss-Krüger points read in the scene's UTM: no points of UTM 32, said at the point.
    std::string wrong = errorOf(cityScene(city, "", true));
    EXPECT_NE(wrong.find("crossing.xml:1:"), std::string::npos) << wrong;
    EXPECT_NE(wrong.find("is no point of EPSG:25832"), std::string::npos) << wrong;
}

}  // namespace
}  // namespace veduta
