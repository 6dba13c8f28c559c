// <slg level="atkis"> (digest-003 §8.3): a landscape's settlement areas filled with SLG blocks,
// lots and buildings, and its building footprints (ALKIS AX_Gebaeude, Objektart 31001) planned
// inside their outlines, every building standing at the lowest terrain point under it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <unistd.h>

#include "assembly/build_scene.h"
#include "city/atkis_slg_input.h"
#include "esri_ascii_grid.h"
#include "geo/edbs.h"
#include "input_error.h"
#include "shared_data.h"
#include "slg/building_plan.h"
#include "slg/face_sides.h"
#include "slg/lot_building.h"
#include "slg/urban_geography_file.h"
#include "test_paths.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

constexpr double kWest = 530000, kSouth = 5326000, kSpacing = 10;
constexpr int kNodes = 41;

// A plane rising 5 % to the east and 3 % to the north.
double height(double x, double y) { return 300 + 0.05 * x + 0.03 * y; }

// Local metres (the origin is the DGM's south-west node) as map coordinates of the GeoJSON.
std::string ring(std::initializer_list<std::pair<double, double>> points) {
    std::string text;
    for (auto [x, y] : points) text += fmt::format("[{}, {}], ", kWest + x, kSouth + y);
    text += fmt::format("[{}, {}]", kWest + points.begin()->first, kSouth + points.begin()->second);
    return "[[" + text + "]]";
}

class AtkisSlg : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
            fmt::format("veduta_atkis_slg_{}_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(),
                        getpid());
        fs::create_directories(dir_);
        std::ofstream(dir_ / "dgm.asc") << test::esriAsciiGrid(
            kNodes, kNodes, kWest, kSouth, kSpacing,
            [](int c, int r) { return fmt::format("{:.3f}", height(c * 10.0, r * 10.0)); });
        // A residential area in the west; an industrial one in the east with two footprints.
        std::ofstream(dir_ / "areas.geojson") << fmt::format(
            R"({{"type": "FeatureCollection",
 "crs": {{"type": "name", "properties": {{"name": "urn:ogc:def:crs:EPSG::25832"}}}},
 "features": [
  {{"type": "Feature", "properties": {{"OBJART": 2111, "OBJID": "W1"}},
   "geometry": {{"type": "Polygon", "coordinates": {}}}}},
  {{"type": "Feature", "properties": {{"OBJART": 2112, "OBJID": "G1"}},
   "geometry": {{"type": "Polygon", "coordinates": {}}}}},
  {{"type": "Feature", "properties": {{"OBJART": 31001, "OBJID": "B1"}},
   "geometry": {{"type": "Polygon", "coordinates": {}}}}},
  {{"type": "Feature", "properties": {{"OBJART": 31001, "OBJID": "B2"}},
   "geometry": {{"type": "Polygon", "coordinates": {}}}}}
 ]}})",
            ring({{20, 20}, {190, 20}, {190, 180}, {20, 180}}), ring({{230, 20}, {380, 20}, {380, 180}, {230, 180}}),
            ring({{250, 40}, {290, 40}, {290, 65}, {250, 65}}),
            ring({{300, 100}, {360, 100}, {360, 130}, {330, 150}, {300, 130}}));
    }
    void TearDown() override { fs::remove_all(dir_); }

    // `landscape`: more attributes of the <landscape>; `more`: more elements of the scene.
    RenderScene scene(const std::string &slg, const std::string &landscape = "") {
        SceneDescription d =
            readSceneText(fmt::format("<scene version=\"1\">\n<georeference crs=\"EPSG:25832\" origin=\"{} {}\"/>\n"
                                      "<camera position=\"200 -300 200\" look_at=\"200 100 300\" up=\"0 0 1\"/>\n"
                                      "<landscape seed=\"4\" trees=\"false\" {}><dgm file=\"dgm.asc\"/>"
                                      "<atkis file=\"areas.geojson\"/></landscape>\n{}\n</scene>\n",
                                      kWest, kSouth, landscape, slg),
                          "test.xml", dir_);
        return buildRenderScene(d, &warnings_);
    }

    fs::path dir_;
    std::vector<std::string> warnings_;
};

std::string atkisSlg(const std::string &more = "") {
    return fmt::format(R"(<slg level="atkis" tables="{}" seed="2" {}/>)",
                       test::sourceFile("rules/slg/urban-geography.xml"), more);
}

uint64_t buildings(const RenderScene &scene) {
    uint64_t n = 0;
    for (const auto &[level, counts] : scene.lods) n += counts.buildings;
    return n;
}

TEST_F(AtkisSlg, SettlementAreasAreFilledAndFootprintsBuiltInside) {
    RenderScene s = scene(atkisSlg());
    // Two footprints and the lots of a 170 × 160 m residential area.
    EXPECT_GT(buildings(s), 10u);
    MaterialId wall = kNoMaterial;
    for (size_t m = 0; m < s.materials.size(); ++m)
        if (s.materials[m].name == "slg/wall") wall = MaterialId(m);
    ASSERT_NE(wall, kNoMaterial);
    size_t inFootprints = 0;
    for (const BakedMesh &baked : s.meshes) {
        const Mesh &mesh = baked.mesh;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            if (mesh.triangleMaterials[t] != wall) continue;
            for (int k = 0; k < 3; ++k) {
                Vec3f p = mesh.positions[mesh.indices[3 * t + k]];
                bool west = p.x >= 20 - 1e-3 && p.x <= 190 + 1e-3 && p.y >= 20 - 1e-3 && p.y <= 180 + 1e-3;
                bool b1 = p.x >= 250 - 1e-3 && p.x <= 290 + 1e-3 && p.y >= 40 - 1e-3 && p.y <= 65 + 1e-3;
                bool b2 = p.x >= 300 - 1e-3 && p.x <= 360 + 1e-3 && p.y >= 100 - 1e-3 && p.y <= 150 + 1e-3;
                // Walls stand in the residential area or in a footprint: none elsewhere in the
                // industrial area, which keeps its footprints.
                ASSERT_TRUE(west || b1 || b2) << p.x << " " << p.y;
                inFootprints += b1 || b2;
            }
        }
    }
    EXPECT_GT(inFootprints, 0u);
}

// structure= and style= on the landscape: its two footprints stand as town houses of modules, each
// at the lowest ground under it; an <slg level="atkis"> beside them
// would build on the same footprints and is refused.
TEST_F(AtkisSlg, AModularLookRaisesTheFootprintsAsModularBuildings) {
    std::string look =
        fmt::format(R"(structure="{}" style="{}")", test::sourceFile("scenes/townhouse/townhouse.structure"),
                    test::sourceFile("scenes/townhouse/ochre.style"));
    std::string materials =
        fmt::format(R"(<materials file="{}"/><material name="interior_dim" diffuse="0.1 0.1 0.1"/>)",
                    test::sourceFile("rules/gruenderzeit/materials.xml"));
    RenderScene s = scene(materials, look);
    ASSERT_EQ(s.buildings.size(), 2u);
    for (const BuildingRecord &b : s.buildings) {
        bool first = b.base < height(300, 100);
        double lowest = first ? height(250, 40) : height(300, 100);
        EXPECT_NEAR(b.base, lowest, 0.01) << b.id;
        EXPECT_NEAR(b.eaves - b.base, 18.6, 1e-3) << "the structure's storeys: ALK counts none";
    }
    EXPECT_NE(test::inputErrorOf([&] { scene(materials + atkisSlg(), look); }).find("not both"), std::string::npos);
}

TEST_F(AtkisSlg, EveryBuildingStandsAtTheLowestGroundUnderIt) {
    RenderScene s = scene(atkisSlg(R"(storeys_within="100000")"));  // a mesh of its own each
    ASSERT_GT(buildings(s), 0u);
    size_t checked = 0;
    for (const BakedMesh &baked : s.meshes) {
        if (baked.buildingId == 0) continue;  // the terrain, the merged boxes
        const Mesh &mesh = baked.mesh;
        float lowest = INFINITY, x = 0, y = 0;
        for (Vec3f p : mesh.positions)
            if (p.z < lowest) lowest = p.z, x = p.x, y = p.y;
        // The plane is exact between the DGM's nodes: the lowest wall foot lies on the ground
        // at the footprint's lowest corner, a lot's lowest corner for a generated building.
        EXPECT_LE(lowest, height(x, y) + 0.01) << x << " " << y;
        EXPECT_GE(lowest, height(x, y) - 0.05 * 40 - 0.03 * 40) << x << " " << y;
        ++checked;
    }
    EXPECT_GT(checked, 0u);
}

TEST_F(AtkisSlg, WithoutALandscapeItSaysWhatItNeeds) {
    std::string error = test::inputErrorOf(
        [&] { buildRenderScene(readSceneText("<scene version=\"1\">" + atkisSlg() + "</scene>", "test.xml", dir_)); });
    EXPECT_NE(error.find("test.xml:1:20: level=\"atkis\" builds on the settlement areas and building footprints of "
                         "the scene's <landscape>; the scene has none"),
              std::string::npos)
        << error;
    EXPECT_NE(test::inputErrorOf([&] {
                  readSceneText(R"(<scene version="1"><slg level="atkis" outline="0 0 1 0 1 1" tables="x"/></scene>)",
                                "test.xml", dir_);
              }).find("leave out outline"),
              std::string::npos);
}

// The ALK sample of LV Sachsen (../shared/data): its Folie 011 footprints, as others drew them,
// are each a simple counter-clockwise outline, and each gets storeys and apartments inside it.
TEST(AtkisSlgInput, TheFootprintsOfARealAlkFileArePlannedInside) {
    auto path = test::sharedDataFile("edbs/alk_muster_part1.edbs");
    if (!path) GTEST_SKIP() << "../shared/data is not here";
    EdbsConversion data = toAtkis(readEdbs(*path), IncompleteObjects::Skip);
    SlgLandInput input = slgLandInput(data.atkis.objects, LocalFrame{{5493000, 5654500}});
    size_t parts = 0;  // of the Gebäude objects (ALK Folie 011) that close
    for (const AtkisObject &object : data.atkis.objects)
        if (landClass(object) == LandClass::Building) parts += object.areas.size();
    ASSERT_GT(parts, 0u);
    EXPECT_EQ(input.footprints.size() + size_t(input.unusable), parts) << "every part a footprint or counted";
    UrbanGeography tables = readUrbanGeography(test::sourceFile("rules/slg/urban-geography.xml"));
    LandUseWeights housing{};
    housing[size_t(LandUse::Wohnen)] = 1;
    size_t planned = 0, apartments = 0, rooms = 0;
    for (const SlgFootprint &footprint : input.footprints) {
        auto building = lotBuilding(tables, {housing, Locality::Mantel, {}}, 7, footprint.identity);
        ASSERT_TRUE(building);
        const BuildingPlanParameters &parameters = building->parameters;
        EXPECT_GT(signedArea(footprint.outline), 0);
        EXPECT_TRUE(isSimple(footprint.outline));
        PlanShape shape{footprint.outline, std::vector<EdgeLocation>(footprint.outline.size(), EdgeLocation::Street)};
        BuildingPlan plan = planInFootprint(shape, fourSides(shape.points, 1), parameters, 7, footprint.identity);
        EXPECT_EQ(plan.placement.footprint.points, footprint.outline);
        EXPECT_EQ(plan.storeys, parameters.storeys);
        planned += !plan.storey.apartments.empty();
        apartments += plan.storey.apartments.size();
        for (const ApartmentPlan &apartment : plan.storey.apartments) rooms += apartment.rooms.size();
    }
    EXPECT_EQ(planned, input.footprints.size());
    EXPECT_GT(rooms, apartments);
    std::printf("ALK sample: %zu footprints, %zu apartments and %zu rooms a storey, %d outlines unusable\n",
                input.footprints.size(), apartments, rooms, input.unusable);
}

}  // namespace
}  // namespace veduta
