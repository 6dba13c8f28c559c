// <landscape> in scene files: the DGM and ATKIS layers read, draped and planted into the
// render scene, buildings seated on the terrain, and the landscape's errors.
#include "geo/generate_landscape.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "assembly/build_scene.h"
#include "city/plinth.h"
#include "esri_ascii_grid.h"
#include "geo/terrain_surface.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

constexpr double kWest = 530000, kSouth = 5326000, kSpacing = 10;
constexpr int kColumns = 21, kRows = 21;

// A slope rising to the north-east with a pit at node (9, 9), inside the house below but
// away from its corners.
double height(int c, int r) { return 500 + 0.8 * c + 0.5 * r - (c == 9 && r == 9 ? 3.0 : 0.0); }

class Landscape : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
            fmt::format("veduta_land_{}_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(), getpid());
        fs::create_directories(dir_);
        write("dgm.asc", test::esriAsciiGrid(kColumns, kRows, kWest, kSouth, kSpacing, [](int c, int r) {
                  return fmt::format("{:.3f}", height(c, r));
              }));
    }
    void TearDown() override { fs::remove_all(dir_); }

    void write(const std::string &name, const std::string &text) const { std::ofstream(dir_ / name) << text; }

    // A scene with the georeference at the grid's centre node (10, 10).
    SceneDescription scene(const std::string &landscape, const std::string &rest = "") const {
        std::string xml = "<scene version=\"1\">\n<georeference crs=\"EPSG:25832\" origin=\"530100 5326100\"/>\n" +
            landscape + rest + "</scene>\n";
        return readSceneText(xml, "test.xml", dir_);
    }

    RenderScene build(const SceneDescription &d, std::vector<std::string> *warnings = nullptr) const {
        return buildRenderScene(d, warnings);
    }

    fs::path dir_;
};

MaterialId materialNamed(const RenderScene &s, const std::string &name) {
    for (MaterialId m = 0; m < s.materials.size(); ++m)
        if (s.materials[m].name == name) return m;
    return kNoMaterial;
}

TEST_F(Landscape, TheTerrainIsTheDgmInTheLocalFrame) {
    RenderScene s = build(scene("<landscape><dgm file=\"dgm.asc\"/></landscape>\n"));
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh &m = s.meshes[0].mesh;
    EXPECT_EQ(m.triangleCount(), size_t(2 * (kColumns - 1) * (kRows - 1)));
    // Node (c, r) lies at (c − 10, r − 10) · 10 m from the origin, at its height.
    std::map<std::pair<int, int>, float> heights;
    for (const Vec3f &p : m.positions)
        heights[{int(std::lround(p.x / kSpacing)) + 10, int(std::lround(p.y / kSpacing)) + 10}] = p.z;
    ASSERT_EQ(heights.size(), size_t(kColumns * kRows));
    for (auto &[node, z] : heights) EXPECT_FLOAT_EQ(z, float(height(node.first, node.second)));
    EXPECT_NE(materialNamed(s, "land/bare"), kNoMaterial);
}

TEST_F(Landscape, NeedsAGeoreference) {
    std::string xml = "<scene version=\"1\">\n<landscape><dgm file=\"dgm.asc\"/></landscape>\n</scene>\n";
    SceneDescription d = readSceneText(xml, "test.xml", dir_);
    EXPECT_EQ(test::inputErrorOf([&] { build(d); }),
              "test.xml:2:1: a <landscape> needs the scene's <georeference crs=\"EPSG:…\" origin=\"E N\">");
}

TEST_F(Landscape, ADgmInAnotherCrsIsAnError) {
    SceneDescription d = scene("<landscape><dgm file=\"dgm.asc\" crs=\"EPSG:31467\"/></landscape>\n");
    std::string error = test::inputErrorOf([&] { build(d); });
    EXPECT_NE(error.find("test.xml:3:23: the DGM is in EPSG:31467 and the scene in EPSG:25832"), std::string::npos)
        << error;
}

TEST_F(Landscape, BadElementsAndAttributesAreErrorsAtTheirPlace) {
    EXPECT_EQ(test::inputErrorOf([&] { scene("<landscape nodata=\"drop\"><dgm file=\"dgm.asc\"/></landscape>\n"); }),
              "test.xml:3:20: nodata is 'fill' or 'cut', not 'drop'");
    EXPECT_EQ(test::inputErrorOf([&] {
                  scene("<landscape nodata=\"cut\" fill_distance=\"4\"><dgm file=\"dgm.asc\"/></landscape>\n");
              }),
              "test.xml:3:40: fill_distance needs nodata=\"fill\"");
    EXPECT_EQ(scene("<landscape fill_distance=\"40\"><dgm file=\"dgm.asc\"/></landscape>\n").landscape->fillDistance,
              40);
    EXPECT_EQ(scene("<landscape><dgm file=\"dgm.asc\"/></landscape>\n").landscape->fillDistance, kDefaultFillDistance);
    EXPECT_EQ(scene("<landscape nodata=\"cut\"><dgm file=\"dgm.asc\"/></landscape>\n").landscape->fillDistance, 0);
    EXPECT_EQ(test::inputErrorOf([&] { scene("<landscape/>\n"); }),
              "test.xml:3:1: a <landscape> needs at least one <dgm file=\"...\"/>");
    EXPECT_EQ(test::inputErrorOf([&] { scene("<landscape><osm file=\"x\"/></landscape>\n"); }),
              "test.xml:3:12: <osm> cannot stand inside <landscape>; expected <dgm> or <atkis>");
}

// The issue's rule: the base is the lowest terrain point under the footprint, interior
// included (the pit is no corner), the plinth reaches below it, and a given base stays.
TEST_F(Landscape, BuildingsStandOnTheLowestTerrainUnderTheirFootprint) {
    std::string buildings = "<buildings rules=\"" + test::sourceFile("rules/gruenderzeit/FacadeStructure.xml") +
        "\">\n"
        "<building footprint=\"-25 -25 5 -25 5 5 -25 5\" street=\"0\"/>\n"
        "<building base=\"600\" footprint=\"30 30 45 30 45 45 30 45\" street=\"0\"/>\n"
        "</buildings>\n";
    RenderScene s = build(scene("<landscape><dgm file=\"dgm.asc\"/></landscape>\n", buildings));
    MaterialId plinth = materialNamed(s, "plinth");
    ASSERT_NE(plinth, kNoMaterial);
    float lowest[3] = {1e9f, 1e9f, 1e9f};  // by building id (0: the terrain), plinths apart
    float lowestPlinth = 1e9f;
    for (const BakedMesh &b : s.meshes) {
        for (size_t t = 0; t < b.mesh.triangleCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                float z = b.mesh.positions[b.mesh.indices[3 * t + k]].z;
                if (b.mesh.triangleMaterials[t] == plinth) lowestPlinth = std::min(lowestPlinth, z);
                else lowest[b.buildingId] = std::min(lowest[b.buildingId], z);
            }
    }
    // The footprint's corners are nodes (7, 7), (10, 7), (10, 10), (7, 10); the lowest corner
    // is 500 + 5.6 + 3.5 = 509.1, the pit at (9, 9) 500 + 7.2 + 4.5 − 3 = 508.7.
    EXPECT_FLOAT_EQ(lowest[1], 508.7f);
    EXPECT_FLOAT_EQ(lowestPlinth, 508.7f - kPlinthDepth);
    EXPECT_FLOAT_EQ(lowest[2], 600.0f);
}

// Ribbons take their pavement's material and roads their rank's markings: a cobbled town
// street, a federal road, a gravel path and a railway.
TEST_F(Landscape, RibbonMaterialsAndMarkingsSwitchWithTheRoadClass) {
    write("traffic.geojson", R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [
  {"type": "Feature", "properties": {"OBJART": 3101, "WDM": "1307", "BRF": "0060", "OFM": "Pflaster"},
   "geometry": {"type": "LineString", "coordinates": [[530005, 5326020], [530195, 5326020]]}},
  {"type": "Feature", "properties": {"OBJART": 3101, "WDM": "1303", "BRF": "0075"},
   "geometry": {"type": "LineString", "coordinates": [[530005, 5326080], [530195, 5326080]]}},
  {"type": "Feature", "properties": {"OBJART": 3102},
   "geometry": {"type": "LineString", "coordinates": [[530005, 5326130], [530195, 5326130]]}},
  {"type": "Feature", "properties": {"OBJART": 3201},
   "geometry": {"type": "LineString", "coordinates": [[530005, 5326170], [530195, 5326170]]}}
 ]})");
    RenderScene s = build(scene("<landscape><dgm file=\"dgm.asc\"/><atkis file=\"traffic.geojson\"/></landscape>\n"));
    // Painted area by the north–south band (local y) of each line.
    MaterialId paint = materialNamed(s, "land/marking");
    ASSERT_NE(paint, kNoMaterial);
    std::map<std::string, double> pavedArea, paintedArea;
    auto band = [](float y) { return y < -60 ? "town" : y < -10 ? "federal" : y < 40 ? "path" : "rail"; };
    for (const BakedMesh &b : s.meshes) {
        for (size_t t = 0; t < b.mesh.triangleCount(); ++t) {
            const std::string &name = s.materials[b.mesh.triangleMaterials[t]].name;
            if (name != "land/marking" && name.find("land/") != 0) continue;
            Vec3f p = b.mesh.positions[b.mesh.indices[3 * t]], q = b.mesh.positions[b.mesh.indices[3 * t + 1]],
                  r = b.mesh.positions[b.mesh.indices[3 * t + 2]];
            double area = 0.5 * std::abs((q.x - p.x) * double(r.y - p.y) - (q.y - p.y) * double(r.x - p.x));
            if (b.mesh.triangleMaterials[t] == paint) paintedArea[band(p.y)] += area;
            else if (name != "land/bare") pavedArea[name + " " + band(p.y)] += area;
        }
    }
    EXPECT_NEAR(pavedArea["land/cobbles town"], 190 * 6.0, 1.0);
    EXPECT_NEAR(pavedArea["land/asphalt federal"], 190 * 7.5, 1.0);
    EXPECT_NEAR(pavedArea["land/gravel path"], 190 * 2.5, 1.0);
    EXPECT_NEAR(pavedArea["land/ballast rail"], 190 * 4.5, 1.0);
    // The town street: dashes of 3 m every 9 m; the federal road: 6 m every 18 m and two edge
    // lines; the path and the railway: none.
    EXPECT_NEAR(paintedArea["town"], (21 * 3 + 1) * 0.12, 0.01);
    EXPECT_NEAR(paintedArea["federal"], 11 * 6 * 0.12 + 2 * 190 * 0.12, 0.01);
    EXPECT_EQ(paintedArea.count("path"), 0u);
    EXPECT_EQ(paintedArea.count("rail"), 0u);
}

// Areas become materials of the terrain, lines ribbons, forests trees; the trees stand on the
// terrain and are the same on every run.
TEST_F(Landscape, AtkisLayersBecomeSurfacesRibbonsAndTrees) {
    write("layer.geojson", R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [
  {"type": "Feature", "properties": {"OBJART": 4107, "VEG": "2000", "OBJID": "F1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530010, 5326010], [530090, 5326010], [530090, 5326090], [530010, 5326090], [530010, 5326010]]]}},
  {"type": "Feature", "properties": {"OBJART": 5112, "OBJID": "W1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530120, 5326120], [530170, 5326125], [530160, 5326170], [530120, 5326120]]]}},
  {"type": "Feature", "properties": {"OBJART": 3101, "BRF": "0065", "OBJID": "R1"},
   "geometry": {"type": "LineString", "coordinates": [[530005, 5326100], [530100, 5326103], [530195, 5326140]]}}
 ]})");
    SceneDescription d =
        scene("<landscape seed=\"7\"><dgm file=\"dgm.asc\"/><atkis file=\"layer.geojson\"/></landscape>\n");
    RenderScene s = build(d);
    for (const char *name : {"land/forest", "land/water", "land/asphalt", "land/marking", "land/bark", "land/needles"})
        EXPECT_NE(materialNamed(s, name), kNoMaterial) << name;
    ASSERT_FALSE(s.instances.empty());
    // Trees in the forest (local −90…−10), each at the terrain's height under it.
    const Mesh &terrain = s.meshes[0].mesh;
    TerrainSurface surface(terrain, {});
    for (const Instance &tree : s.instances) {
        Vec3f at{tree.objectToWorld.m[3], tree.objectToWorld.m[7], tree.objectToWorld.m[11]};
        EXPECT_GE(at.x, -90.0f);
        EXPECT_LE(at.x, -10.0f);
        std::optional<double> ground = surface.heightAt({at.x, at.y});
        ASSERT_TRUE(ground);
        EXPECT_NEAR(at.z, *ground, 1e-3);
    }
    RenderScene again = build(d);
    ASSERT_EQ(again.instances.size(), s.instances.size());
    for (size_t i = 0; i < s.instances.size(); ++i)
        EXPECT_EQ(again.instances[i].objectToWorld, s.instances[i].objectToWorld);
}

// A forest with a road through it and a pond in it: no tree on the road or in the pond.
TEST_F(Landscape, TreesKeepOffRoadsAndWater) {
    write("forest.geojson", R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [
  {"type": "Feature", "properties": {"OBJART": 4107, "OBJID": "F1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530010, 5326010], [530190, 5326010], [530190, 5326190], [530010, 5326190], [530010, 5326010]]]}},
  {"type": "Feature", "properties": {"OBJART": 5112, "OBJID": "W1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530120, 5326120], [530170, 5326120], [530170, 5326170], [530120, 5326170], [530120, 5326120]]]}},
  {"type": "Feature", "properties": {"OBJART": 3101, "BRF": "0060", "OBJID": "R1"},
   "geometry": {"type": "LineString", "coordinates": [[530000, 5326080], [530200, 5326080]]}}
 ]})");
    RenderScene s = build(scene("<landscape><dgm file=\"dgm.asc\"/><atkis file=\"forest.geojson\"/></landscape>\n"));
    ASSERT_GT(s.instances.size(), 500u);
    for (const Instance &tree : s.instances) {
        float x = tree.objectToWorld.m[3], y = tree.objectToWorld.m[7];        // local: the origin is (530100, 5326100)
        EXPECT_GE(std::abs(y - -20.0f), 3.0f + 1.5f) << x << ", " << y;        // the road: 6 m wide, 1.5 m clearance
        EXPECT_FALSE(x > 20 && x < 70 && y > 20 && y < 70) << x << ", " << y;  // the pond
    }
}

// Trees of a forest (local x −90…−10) and of a grove east of it (x 20…90), neither with an id.
constexpr const char *kForest = R"(
  {"type": "Feature", "properties": {"OBJART": 4107},
   "geometry": {"type": "Polygon", "coordinates": [[[530010, 5326010], [530090, 5326010], [530090, 5326090], [530010, 5326090], [530010, 5326010]]]}})";
constexpr const char *kGrove = R"(
  {"type": "Feature", "properties": {"OBJART": 4107},
   "geometry": {"type": "Polygon", "coordinates": [[[530120, 5326010], [530190, 5326010], [530190, 5326090], [530120, 5326090], [530120, 5326010]]]}})";

std::string layer(const std::string &features) {
    return R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [)" +
        features + "]}";
}

std::vector<Transform> treesOf(const RenderScene &s) {
    std::vector<Transform> trees;
    for (const Instance &tree : s.instances) trees.push_back(tree.objectToWorld);
    return trees;
}

// Where the trees stand and what the tree models look like.
std::pair<std::vector<Transform>, std::vector<std::vector<Vec3f>>> treesAndModelsOf(const RenderScene &s) {
    std::vector<std::vector<Vec3f>> models;
    for (const Mesh &m : s.prototypes) models.push_back(m.positions);
    return {treesOf(s), models};
}

TEST_F(Landscape, TreesDrawWithTheSceneSeedUnlessTheLandscapeGivesOne) {
    write("forest.geojson", layer(kForest));
    auto trees = [&](uint32_t sceneSeed, const std::string &own) {
        SceneDescription d =
            scene("<landscape " + own + "><dgm file=\"dgm.asc\"/><atkis file=\"forest.geojson\"/></landscape>\n");
        d.seed = sceneSeed;  // as --seed sets it
        return treesAndModelsOf(build(d));
    };
    auto atZero = trees(0, "");
    ASSERT_FALSE(atZero.first.empty());
    auto atFive = trees(5, "");
    EXPECT_NE(atFive.first, atZero.first);    // the places
    EXPECT_NE(atFive.second, atZero.second);  // the models
    EXPECT_EQ(trees(5, "seed=\"0\""), atZero);
}

// An object without an id is known by its kind and geometry, not by its place in the layer.
TEST_F(Landscape, AnObjectWithoutIdKeepsItsTreesWhenAnotherComesBeforeIt) {
    auto groveTrees = [&](const std::string &features) {
        write("trees.geojson", layer(features));
        std::vector<Transform> grove;
        RenderScene s = build(scene("<landscape><dgm file=\"dgm.asc\"/><atkis file=\"trees.geojson\"/></landscape>\n"));
        for (const Transform &t : treesOf(s))
            if (t.m[3] > 10) grove.push_back(t);
        return grove;
    };
    std::vector<Transform> alone = groveTrees(kGrove);
    ASSERT_FALSE(alone.empty());
    EXPECT_EQ(groveTrees(std::string(kForest) + "," + kGrove), alone);
}

TEST_F(Landscape, TooManyTreesIsAnError) {
    write("forest.geojson", R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}}, "features": [
  {"type": "Feature", "properties": {"OBJART": 4107},
   "geometry": {"type": "Polygon", "coordinates": [[[530010, 5326010], [530190, 5326010], [530190, 5326190], [530010, 5326190], [530010, 5326010]]]}}]})");
    SceneDescription d =
        scene("<landscape tree_budget=\"50\"><dgm file=\"dgm.asc\"/><atkis file=\"forest.geojson\"/></landscape>\n");
    EXPECT_EQ(test::inputErrorOf([&] { build(d); }),
              "test.xml:3:1: the landscape would have more than 50 trees (tree_budget); raise tree_budget or set "
              "trees=\"false\"");
}

// GeoJSON without a crs member is WGS 84 (RFC 7946): UTM coordinates in it are no longitudes.
TEST_F(Landscape, PointsOutsideTheirCrsAreErrorsNamingTheObject) {
    write("lonlat.geojson", R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"OBJART": 4107},
   "geometry": {"type": "Polygon", "coordinates": [[[530010, 5326010], [530190, 5326010], [530190, 5326190], [530010, 5326010]]]}}]})");
    SceneDescription d = scene("<landscape><dgm file=\"dgm.asc\"/><atkis file=\"lonlat.geojson\"/></landscape>\n");
    std::string error = test::inputErrorOf([&] { build(d); });
    EXPECT_NE(error.find("test.xml:3:46: "), std::string::npos) << error;
    EXPECT_NE(error.find("lonlat.geojson: layer lonlat, feature 0: (530010, 5326010) is no point of EPSG:4326"),
              std::string::npos)
        << error;
}

}  // namespace
}  // namespace veduta
