// CityGML building models as real files hold them (../shared/data/citygml: KIT's FZK-Haus and
// two Bavarian LoD2 buildings made of xlink:href surfaces) and as small files written here:
// a LoD1 box, a wall with a window hole, and hostile ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "city/citygml_file.h"
#include "city/citygml_measures.h"
#include "input_error.h"
#include "shared_data.h"
#include "test_paths.h"

namespace veduta {
namespace {

std::map<SurfaceKind, int> kindsOf(const CityGmlBuilding &building) {
    std::map<SurfaceKind, int> kinds;
    for (const CityGmlPolygon &polygon : building.polygons) ++kinds[polygon.kind];
    return kinds;
}

std::filesystem::path writeFile(const std::string &name, const std::string &text) {
    std::filesystem::path file = std::filesystem::temp_directory_path() / ("veduta-citygml-" + name);
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

constexpr const char *kHeader =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml">
<gml:boundedBy><gml:Envelope srsName="urn:ogc:def:crs:EPSG::25832" srsDimension="3"><gml:lowerCorner>500000 5400000 0</gml:lowerCorner><gml:upperCorner>500010 5400008 6</gml:upperCorner></gml:Envelope></gml:boundedBy>
)";

std::string polygonXml(const std::string &id, const std::vector<std::vector<double>> &rings) {
    std::string xml = fmt::format(R"(<gml:Polygon gml:id="{}">)", id);
    for (size_t r = 0; r < rings.size(); ++r) {
        std::string list;
        const std::vector<double> &ring = rings[r];
        for (size_t i = 0; i < ring.size(); i += 3)
            list += fmt::format("{} {} {} ", 500000 + ring[i], 5400000 + ring[i + 1], ring[i + 2]);
        list += fmt::format("{} {} {}", 500000 + ring[0], 5400000 + ring[1], ring[2]);  // closed, as GML wants
        xml += fmt::format("<gml:{0}><gml:LinearRing><gml:posList>{1}</gml:posList></gml:LinearRing></gml:{0}>",
                           r == 0 ? "exterior" : "interior", list);
    }
    return xml + "</gml:Polygon>";
}

// A 10 × 8 × 6 m box as a LoD1 solid, each face counter-clockwise seen from outside.
std::string lod1Box() {
    std::vector<std::vector<double>> faces{
        {0, 0, 0, 0, 8, 0, 10, 8, 0, 10, 0, 0}, {0, 0, 6, 10, 0, 6, 10, 8, 6, 0, 8, 6},
        {0, 0, 0, 10, 0, 0, 10, 0, 6, 0, 0, 6}, {10, 0, 0, 10, 8, 0, 10, 8, 6, 10, 0, 6},
        {10, 8, 0, 0, 8, 0, 0, 8, 6, 10, 8, 6}, {0, 8, 0, 0, 0, 0, 0, 0, 6, 0, 8, 6},
    };
    std::string xml = std::string(kHeader) +
        R"(<core:cityObjectMember><bldg:Building gml:id="BOX"><bldg:measuredHeight uom="m">6</bldg:measuredHeight>
<bldg:storeysAboveGround>2</bldg:storeysAboveGround><bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface>)";
    for (size_t f = 0; f < faces.size(); ++f)
        xml += "<gml:surfaceMember>" + polygonXml(fmt::format("F{}", f), {faces[f]}) + "</gml:surfaceMember>";
    return xml +
        "</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid></bldg:Building>"
        "</core:cityObjectMember></core:CityModel>\n";
}

// One LoD2 wall surface (10 × 6 m, facing south) with a 2 × 2 m window hole.
std::string wallWithHole() {
    return std::string(kHeader) +
        R"(<core:cityObjectMember><bldg:Building gml:id="WALL"><bldg:boundedBy><bldg:WallSurface gml:id="W"><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember>)" +
        polygonXml("P", {{0, 0, 0, 10, 0, 0, 10, 0, 6, 0, 0, 6}, {4, 0, 2, 4, 0, 4, 6, 0, 4, 6, 0, 2}}) +
        "</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface></bldg:WallSurface></bldg:boundedBy>"
        "</bldg:Building></core:cityObjectMember></core:CityModel>\n";
}

TEST(CityGml, TheFzkHouseHasItsSevenSurfacesClosedAtItsTruePlace) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    CityGmlModel model = readCityGml(*file);
    EXPECT_EQ(model.srsName, "urn:adv:crs:ETRS89_UTM32");
    EXPECT_EQ(model.epsg, 25832);
    ASSERT_TRUE(model.envelopeLow && model.envelopeHigh);
    EXPECT_EQ(model.envelopeLow->x, 458877);
    EXPECT_EQ(model.envelopeHigh->y, 5438363);
    ASSERT_EQ(model.buildings.size(), 1u);
    const CityGmlBuilding &house = model.buildings[0];
    EXPECT_EQ(house.id, "UUID_d281adfc-4901-0f52-540b-4cc1a9325f82");
    EXPECT_EQ(house.lod, 2u);
    // The lod2Solid names the seven thematic surfaces' polygons: each is taken once.
    EXPECT_EQ(kindsOf(house),
              (std::map<SurfaceKind, int>{{SurfaceKind::Wall, 4}, {SurfaceKind::Roof, 2}, {SurfaceKind::Ground, 1}}));
    EXPECT_EQ(house.measuredHeight, 6.52);
    EXPECT_EQ(house.roofType, "1030");
    EXPECT_EQ(house.storeysAboveGround, 2);
    EXPECT_EQ(house.function, "1000");

    double ridge = -1e9;
    for (const CityGmlPolygon &polygon : house.polygons)
        for (const CrsCoordinate &p : polygon.rings[0])
            if (polygon.kind == SurfaceKind::Roof) ridge = std::max(ridge, p.z);
    EXPECT_EQ(ridge, 6.31769145362398);  // the file's ridge, to the last digit it writes

    // A 12 × 10 m box from −0.2 m to the eaves at 3.431 m and a gable roof 2.887 m high on it.
    SurfaceSums s = sumSurfaces(house, *model.envelopeLow);
    double eaves = 3.43094010767585, rise = 6.31769145362398 - eaves;
    EXPECT_NEAR(s.volume, 120 * (eaves + 0.2) + 0.5 * 10 * rise * 12, 1e-6);
    EXPECT_NEAR(std::hypot(s.vx, s.vy, s.vz), 0, 1e-6 * s.area);
}

TEST(CityGml, TheBavarianBuildingsCloseTheirSolidsFromXlinkSurfaces) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/citygml_lod2_713_5322.xml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    CityGmlModel model = readCityGml(*file);
    EXPECT_EQ(model.epsg, 25832);  // urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH
    ASSERT_EQ(model.buildings.size(), 2u);
    int surfaces = 0;
    for (const CityGmlBuilding &building : model.buildings) {
        EXPECT_TRUE(building.id.starts_with("DEBY_LOD2_")) << building.id;
        EXPECT_EQ(building.lod, 2u);
        SurfaceSums s = sumSurfaces(building, *model.envelopeLow);
        EXPECT_GT(s.volume, 10) << building.id;
        EXPECT_NEAR(std::hypot(s.vx, s.vy, s.vz), 0, 1e-6 * s.area) << building.id << ": the solid is not closed";
        for (auto [kind, n] : kindsOf(building)) surfaces += n;
        EXPECT_TRUE(building.roofType.size() == 4) << building.roofType;
    }
    EXPECT_EQ(surfaces, 15 + 9 + 2);  // the file's WallSurfaces, RoofSurfaces and GroundSurfaces
    EXPECT_EQ(model.skippedPolygons, 0u);
    // libcitygml skips the AdV externalReference it does not know; the warning says where.
    ASSERT_FALSE(model.warnings.empty());
    EXPECT_NE(model.warnings[0].find("citygml_lod2_713_5322.xml:15:20: "), std::string::npos) << model.warnings[0];
}

TEST(CityGml, ALod1SolidTakesItsKindsFromItsNormals) {
    CityGmlModel model = readCityGml(writeFile("box.gml", lod1Box()));
    EXPECT_EQ(model.epsg, 25832);
    ASSERT_EQ(model.buildings.size(), 1u);
    const CityGmlBuilding &box = model.buildings[0];
    EXPECT_EQ(box.lod, 1u);
    EXPECT_EQ(kindsOf(box),
              (std::map<SurfaceKind, int>{{SurfaceKind::Wall, 4}, {SurfaceKind::Roof, 1}, {SurfaceKind::Ground, 1}}));
    EXPECT_EQ(box.measuredHeight, 6);
    EXPECT_EQ(box.storeysAboveGround, 2);
    SurfaceSums s = sumSurfaces(box, {500000, 5400000, 0});
    EXPECT_NEAR(s.volume, 480, 1e-9);
    EXPECT_NEAR(s.area, 2 * (80 + 60 + 48), 1e-9);
}

TEST(CityGml, ASecondPolygonOfOneIdIsLeftOutWithAWarning) {
    std::string box = lod1Box();
    box.replace(box.find("gml:id=\"F1\""), 11, "gml:id=\"F0\"");
    CityGmlModel model = readCityGml(writeFile("twice.gml", box));
    ASSERT_EQ(model.buildings.size(), 1u);
    EXPECT_EQ(model.buildings[0].polygons.size(), 5u);
    EXPECT_EQ(model.skippedPolygons, 1u);
    // libcitygml warns of the repeated id too; veduta says what it left out.
    EXPECT_TRUE(std::any_of(model.warnings.begin(), model.warnings.end(), [](const std::string &w) {
        return w.find("building BOX: a second polygon of gml:id F0 is left out") != std::string::npos;
    })) << fmt::format("{}", fmt::join(model.warnings, "\n"));
}

TEST(CityGml, TheLodRangeChoosesWhatIsRead) {
    std::filesystem::path file = writeFile("box-lod.gml", lod1Box());
    CityGmlModel model = readCityGml(file, {.minLod = 2, .maxLod = 2});
    EXPECT_TRUE(model.buildings.empty());
    EXPECT_EQ(model.buildingsWithoutGeometry, 1u);
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_NE(model.warnings[0].find("building BOX has no polygon of LoD 2 to 2 (it has LoD 1)"), std::string::npos)
        << model.warnings[0];
}

TEST(CityGml, AHoleIsLeftOpen) {
    CityGmlModel model = readCityGml(writeFile("hole.gml", wallWithHole()));
    ASSERT_EQ(model.buildings.size(), 1u);
    ASSERT_EQ(model.buildings[0].polygons.size(), 1u);
    const CityGmlPolygon &wall = model.buildings[0].polygons[0];
    EXPECT_EQ(wall.kind, SurfaceKind::Wall);
    EXPECT_EQ(wall.rings.size(), 2u);
    SurfaceSums s = sumSurfaces(model.buildings[0], {500000, 5400000, 0});
    EXPECT_NEAR(s.area, 60 - 4, 1e-9);
    EXPECT_NEAR(s.vy, -(60 - 4), 1e-9);  // facing south, as its outline runs
}

const CityGmlPolygon &polygonOf(const CityGmlBuilding &building, const std::string &id) {
    auto it = std::find_if(building.polygons.begin(), building.polygons.end(),
                           [&](const CityGmlPolygon &p) { return p.id == id; });
    if (it == building.polygons.end()) throw std::runtime_error("no polygon " + id);
    return *it;
}

TEST(CityGml, ATextureGivesItsImageAndTheCoordinatesOfEveryRingPoint) {
    std::filesystem::path file = test::sourceFile("tests/data/citygml/textured-house.gml");
    CityGmlModel model = readCityGml(file);
    ASSERT_EQ(model.buildings.size(), 1u);
    const CityGmlBuilding &house = model.buildings[0];
    ASSERT_EQ(house.polygons.size(), 6u);

    // The south wall and its window hole: u = x / 10, v = z / 6, through "appearance\facade.png".
    const CityGmlPolygon &south = polygonOf(house, "S");
    EXPECT_EQ(south.texture, file.parent_path() / "appearance/facade.png");
    ASSERT_EQ(south.uvs.size(), 8u);
    size_t k = 0;
    for (const auto &ring : south.rings)
        for (const CrsCoordinate &p : ring) {
            EXPECT_NEAR(south.uvs[k].x, (p.x - 500000) / 10, 1e-6) << k;
            EXPECT_NEAR(south.uvs[k].y, p.z / 6, 1e-6) << k;
            ++k;
        }
    // The image of the east wall is not there; the reader does not look (the scene does).
    EXPECT_EQ(polygonOf(house, "E").texture, file.parent_path() / "appearance/missing.jpg");
    EXPECT_EQ(polygonOf(house, "E").uvs.size(), 4u);
    // Three texture coordinates for a ring of five positions (four points, closed): the wall is kept, without its
    // texture.
    const CityGmlPolygon &north = polygonOf(house, "N");
    EXPECT_TRUE(north.texture.empty());
    EXPECT_TRUE(north.uvs.empty());
    EXPECT_EQ(model.untexturedPolygons, 1u);
    std::string said = fmt::format("{}", fmt::join(model.warnings, "\n"));
    EXPECT_NE(said.find("building TEXHOUSE: polygon N has 3 texture coordinates for the 5 points of ring N_0; it "
                        "is drawn without its texture"),
              std::string::npos)
        << said;
    // The west wall's X3DMaterial, of the same theme.
    const CityGmlPolygon &west = polygonOf(house, "W");
    EXPECT_TRUE(west.texture.empty());
    ASSERT_TRUE(west.diffuse.has_value());
    EXPECT_NEAR(west.diffuse->y, 0.6f, 1e-6);
    EXPECT_FALSE(polygonOf(house, "R").diffuse.has_value());
}

TEST(CityGml, SrsNamesGiveTheirEpsgCode) {
    EXPECT_EQ(gmlSrsEpsg("EPSG:25832"), 25832);
    EXPECT_EQ(gmlSrsEpsg("urn:ogc:def:crs:EPSG::25833"), 25833);
    EXPECT_EQ(gmlSrsEpsg("urn:ogc:def:crs:EPSG:6.12:31467"), 31467);
    EXPECT_EQ(gmlSrsEpsg("http://www.opengis.net/def/crs/EPSG/0/25832"), 25832);
    EXPECT_EQ(gmlSrsEpsg("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837"), 25832);
    EXPECT_EQ(gmlSrsEpsg("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH"), 25832);
    EXPECT_EQ(gmlSrsEpsg("urn:adv:crs:DE_DHDN_3GK3*DE_DHHN92_NH"), 31467);
    EXPECT_EQ(gmlSrsEpsg(""), 0);
    EXPECT_EQ(gmlSrsEpsg("Local"), 0);
    EXPECT_EQ(gmlSrsEpsg("EPSG:"), 0);
    EXPECT_EQ(gmlSrsEpsg("EPSG:25832x"), 0);
}

TEST(CityGml, HostileFilesAreRefusedWithTheirPlace) {
    std::string laughs = test::inputErrorOf([] {
        readCityGml(writeFile("laughs.gml",
                              "<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [<!ENTITY lol \"lol\">]>\n"
                              "<core:CityModel/>\n"));
    });
    EXPECT_NE(laughs.find("laughs.gml:2:1: the XML file has a document type declaration"), std::string::npos) << laughs;
    EXPECT_NE(laughs.find("does not give it to libcitygml"), std::string::npos) << laughs;

    std::string cut = test::inputErrorOf([] { readCityGml(writeFile("cut.gml", lod1Box().substr(0, 900))); });
    EXPECT_TRUE(std::regex_search(cut, std::regex(R"(cut\.gml:[1-9]\d*:[1-9]\d*: the XML parser stops here: )")))
        << cut;

    EXPECT_NE(test::inputErrorOf([] {
                  readCityGml(writeFile("text.gml", "no XML at all\n"));
              }).find("the XML parser stops here"),
              std::string::npos);
    EXPECT_NE(
        test::inputErrorOf([] { readCityGml(std::filesystem::temp_directory_path()); }).find("is not a regular file"),
        std::string::npos);

    // A polygon of a million points in one posList: libcitygml would keep only its last MiB.
    std::vector<double> circle;
    for (int i = 0; i < 1'000'000; ++i) {
        double a = 2 * M_PI * i / 1'000'000;
        circle.insert(circle.end(), {5 + 5 * std::cos(a), 4 + 4 * std::sin(a), 0});
    }
    std::string huge = std::string(kHeader) +
        R"(<core:cityObjectMember><bldg:Building gml:id="HUGE"><bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface><gml:surfaceMember>)" +
        polygonXml("ROUND", {circle}) +
        "</gml:surfaceMember></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod1Solid>"
        "</bldg:Building></core:cityObjectMember></core:CityModel>\n";
    std::string longText = test::inputErrorOf([&] { readCityGml(writeFile("huge.gml", huge)); });
    EXPECT_NE(longText.find("huge.gml:4:"), std::string::npos) << longText;
    EXPECT_NE(longText.find("a text of more than 1000000 characters starts here"), std::string::npos) << longText;

    // As many points one <gml:pos> each: past the polygon limit, refused before triangulation.
    std::string points;
    for (int i = 0; i < 150'000; ++i) {
        double a = 2 * M_PI * i / 150'000;
        points += fmt::format("<gml:pos>{} {} 0</gml:pos>", 500005 + 5 * std::cos(a), 5400004 + 4 * std::sin(a));
    }
    std::string many = std::string(kHeader) +
        R"(<core:cityObjectMember><bldg:Building gml:id="MANY"><bldg:lod1Solid><gml:Solid><gml:exterior><gml:CompositeSurface><gml:surfaceMember><gml:Polygon gml:id="ROUND"><gml:exterior><gml:LinearRing>)" +
        points +
        "</gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:CompositeSurface>"
        "</gml:exterior></gml:Solid></bldg:lod1Solid></bldg:Building></core:cityObjectMember>"
        "</core:CityModel>\n";
    std::string tooMany = test::inputErrorOf([&] { readCityGml(writeFile("many.gml", many)); });
    EXPECT_NE(tooMany.find("polygon ROUND of building MANY has 150000 points, more than the 100000"), std::string::npos)
        << tooMany;
}

TEST(CityGml, DeepNestingAndBrokenLinksEndInWarningsNotACrash) {
    std::string deep = std::string(kHeader);
    for (int i = 0; i < 100'000; ++i) deep += "<core:x>";
    for (int i = 0; i < 100'000; ++i) deep += "</core:x>";
    deep += "</core:CityModel>\n";
    CityGmlModel nested = readCityGml(writeFile("deep.gml", deep));
    EXPECT_TRUE(nested.buildings.empty());
    EXPECT_FALSE(nested.warnings.empty());

    std::string broken = std::string(kHeader) +
        R"(<core:cityObjectMember><bldg:Building gml:id="LINKS"><bldg:lod2Solid><gml:Solid><gml:exterior><gml:CompositeSurface>
<gml:surfaceMember xlink:href="#NOWHERE" xmlns:xlink="http://www.w3.org/1999/xlink"/></gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid></bldg:Building></core:cityObjectMember></core:CityModel>
)";
    CityGmlModel links = readCityGml(writeFile("links.gml", broken));
    EXPECT_TRUE(links.buildings.empty());
    EXPECT_EQ(links.buildingsWithoutGeometry, 1u);
}

}  // namespace
}  // namespace veduta
