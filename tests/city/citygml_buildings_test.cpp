// The <citygml> element: CityGML buildings placed in the scene's frame at their true size and
// place, one object per building, and the errors a scene gets for what it lacks.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "assembly/build_scene.h"
#include "city/citygml_buildings.h"
#include "input_error.h"
#include "shared_data.h"
#include "test_paths.h"

namespace veduta {
namespace {

RenderScene build(const std::string &xml, std::vector<std::string> *warnings = nullptr) {
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), warnings);
}

std::string fzkScene(const std::string &file, const std::string &extra = "") {
    return fmt::format(
        "<scene version=\"1\"><georeference crs=\"EPSG:25832\" origin=\"458883 5438358\"/>"
        "<citygml file=\"{}\"{}/></scene>",
        file, extra);
}

TEST(CityGmlBuildings, TheFzkHouseStandsAtItsTrueSizeAndPlace) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/FZK-House-LoD2-KIT-IAI-KHH-V2.gml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    RenderScene scene = build(fzkScene(file->string()));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const BakedMesh &house = scene.meshes[0];
    EXPECT_EQ(house.buildingId, cityGmlBuildingId("UUID_d281adfc-4901-0f52-540b-4cc1a9325f82"));
    Vec3f low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (const Vec3f &p : house.mesh.positions) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    // The file's envelope, 458877 5438353 −0.2 to 458889 5438363 6.3177, about the origin; the
    // ridge where the file puts it, within 1 cm.
    EXPECT_NEAR(low.x, -6, 1e-4);
    EXPECT_NEAR(high.x, 6, 1e-4);
    EXPECT_NEAR(low.y, -5, 1e-4);
    EXPECT_NEAR(high.y, 5, 1e-4);
    EXPECT_NEAR(low.z, -0.2, 1e-4);
    EXPECT_NEAR(high.z, 6.31769145362398, 0.01);
    // The north roof in the file's X3DMaterial (diffuse 0.996 0 0), the rest in the materials of
    // their kinds.
    std::set<std::string> materials;
    for (MaterialId m : house.mesh.triangleMaterials) materials.insert(scene.materials[m].name);
    EXPECT_EQ(
        materials,
        (std::set<std::string>{"citygml/x3d/0.996,0.000,0.000", "citygml/roof", "citygml/wall", "citygml/ground"}))
        << fmt::format("{}", fmt::join(materials, ", "));
}

TEST(CityGmlBuildings, EachBavarianBuildingIsAnObjectOfItsOwnId) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/citygml_lod2_713_5322.xml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    std::vector<std::string> warnings;
    RenderScene scene = build(fmt::format("<scene version=\"1\"><georeference crs=\"EPSG:25832\" "
                                          "origin=\"713500 5322750\"/><citygml file=\"{}\"/></scene>",
                                          file->string()),
                              &warnings);
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_NE(scene.meshes[0].buildingId, scene.meshes[1].buildingId);
    EXPECT_EQ(scene.meshes[0].objectId, scene.meshes[1].objectId);
    EXPECT_FALSE(warnings.empty());  // libcitygml's, about the AdV externalReference
}

TEST(CityGmlBuildings, TheBoundingBoxKeepsTheBuildingsCentredInIt) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/citygml_lod2_713_5322.xml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    auto scene = [&](const std::string &bbox, std::vector<std::string> &warnings) {
        return build(fmt::format("<scene version=\"1\"><georeference crs=\"EPSG:25832\" origin=\"713500 5322750\"/>"
                                 "<citygml file=\"{}\" bbox=\"{}\"/></scene>",
                                 file->string(), bbox),
                     &warnings);
    };
    std::vector<std::string> all, west, none;
    EXPECT_EQ(scene("713000 5322000 714000 5323000", all).meshes.size(), 2u);
    EXPECT_NE(all.back().find("the bbox keeps 2 of the file's 2 buildings"), std::string::npos) << all.back();
    // The envelope spans 713229 to 713795: the west half holds one of the two.
    EXPECT_EQ(scene("713000 5322000 713500 5323000", west).meshes.size(), 1u);
    EXPECT_EQ(scene("0 0 1 1", none).meshes.size(), 0u);
    EXPECT_NE(test::inputErrorOf([&] { scene("1 2 0 3", none); }).find("bbox takes four numbers"), std::string::npos);
}

TEST(CityGmlBuildings, TexturedSurfacesShowTheirImage) {
    std::filesystem::path file = test::sourceFile("tests/data/citygml/textured-house.gml");
    std::vector<std::string> warnings;
    RenderScene scene =
        build(fmt::format("<scene version=\"1\"><georeference crs=\"EPSG:25832\" origin=\"500005 5400004\"/>"
                          "<citygml file=\"{}\"/></scene>",
                          file.string()),
              &warnings);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh &house = scene.meshes[0].mesh;
    ASSERT_EQ(house.uvs.size(), house.positions.size());
    ASSERT_TRUE(scene.textures);
    std::string facade = "citygml/texture/" + (file.parent_path() / "appearance/facade.png").generic_string();
    // The facade image is red left of u = 0.5, blue right of it; the south wall's triangles show
    // it where their texture coordinates say.
    int red = 0, blue = 0;
    for (size_t t = 0; t < house.triangleMaterials.size(); ++t) {
        const Material &m = scene.materials[house.triangleMaterials[t]];
        if (m.name != facade) continue;
        ASSERT_NE(m.diffuseMap, kNoTexture);
        Vec2f centre{0, 0};
        for (int k = 0; k < 3; ++k) {
            Vec2f uv = house.uvs[house.indices[3 * t + k]];
            centre = {centre.x + uv.x / 3, centre.y + uv.y / 3};
        }
        float rgb[3];
        scene.textures->lookup(m.diffuseMap, centre, 0.01f, rgb, 3);
        if (centre.x < 0.45f) red += rgb[0] > 3 * rgb[2];
        if (centre.x > 0.55f) blue += rgb[2] > 3 * rgb[0];
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(blue, 0);
    // The east wall's image is not there: said once, and the wall takes the wall material, as does
    // the north wall whose coordinates do not fit.
    std::string said = fmt::format("{}", fmt::join(warnings, "\n"));
    EXPECT_NE(said.find("missing.jpg"), std::string::npos) << said;
    EXPECT_NE(said.find("; 1 polygon(s) are drawn without it"), std::string::npos) << said;
    std::set<std::string> materials;
    for (MaterialId m : house.triangleMaterials) materials.insert(scene.materials[m].name);
    EXPECT_EQ(materials,
              (std::set<std::string>{facade, "citygml/wall", "citygml/x3d/0.200,0.600,0.200", "citygml/roof",
                                     "citygml/ground"}))
        << fmt::format("{}", fmt::join(materials, ", "));
}

std::string texturedHouseFrom(const std::string &cameraAt, const std::string &extra = "") {
    return fmt::format(
        "<scene version=\"1\"><georeference crs=\"EPSG:25832\" origin=\"500005 5400004\"/>"
        "<camera position=\"{}\" look_at=\"0 0 3\"/><citygml file=\"{}\"{}/></scene>",
        cameraAt, test::sourceFile("tests/data/citygml/textured-house.gml"), extra);
}

uint64_t buildingsAt(const RenderScene &scene, const std::string &level) {
    auto it = scene.lods.find(level);
    return it == scene.lods.end() ? 0 : it->second.buildings;
}

// Three kilometres away the house spans about 2 pixels: a box of its footprint up to half way
// between eaves and ridge, in a mesh shared by the boxes (no building id), its record kept.
TEST(CityGmlBuildings, BuildingsTooSmallInTheImageAreBoxes) {
    RenderScene near = build(texturedHouseFrom("0 -30 5"));
    EXPECT_EQ(buildingsAt(near, "citygml/file"), 1u);
    EXPECT_EQ(buildingsAt(near, "citygml/box"), 0u);
    RenderScene far = build(texturedHouseFrom("0 -3000 50"));
    ASSERT_EQ(buildingsAt(far, "citygml/box"), 1u);
    EXPECT_EQ(far.lods.at("citygml/box").merged, 1u);
    ASSERT_EQ(far.meshes.size(), 1u);
    EXPECT_EQ(far.meshes[0].buildingId, 0u);
    ASSERT_EQ(far.buildings.size(), 1u);
    const BuildingRecord &record = far.buildings[0];
    float top = -1e30f, bottom = 1e30f;
    for (Vec3f p : far.meshes[0].mesh.positions) top = std::max(top, p.z), bottom = std::min(bottom, p.z);
    EXPECT_NEAR(top, (record.eaves + record.ridge) / 2, 1e-3f);
    EXPECT_NEAR(bottom, record.base, 1e-3f);
    EXPECT_LT(far.meshes[0].mesh.triangleCount(), near.meshes[0].mesh.triangleCount());
    // A closed prism: four walls of two triangles and a roof of two on the house's rectangle.
    EXPECT_EQ(far.meshes[0].mesh.triangleCount(), 10u);
    // coarse_below_px="0" keeps it as the file has it; coarse_beyond="100" makes it a box again.
    EXPECT_EQ(buildingsAt(build(texturedHouseFrom("0 -3000 50", " coarse_below_px=\"0\"")), "citygml/file"), 1u);
    EXPECT_EQ(buildingsAt(build(texturedHouseFrom("0 -300 5", " coarse_below_px=\"0\" coarse_beyond=\"100\"")),
                          "citygml/box"),
              1u);
}

// Past the geometry budget the farther of the two Bavarian buildings becomes a box, with a warning.
TEST(CityGmlBuildings, TheGeometryBudgetMakesTheFarthestBuildingsBoxes) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("citygml/citygml_lod2_713_5322.xml");
    if (!file) GTEST_SKIP() << "../shared/data/citygml is not there";
    SceneDescription d = readSceneText(fmt::format("<scene version=\"1\"><georeference crs=\"EPSG:25832\" "
                                                   "origin=\"713500 5322750\"/><citygml file=\"{}\"/></scene>",
                                                   file->string()),
                                       "test.xml", test::sourceFile("scenes"));
    d.cityGml[0].coarse.belowPixels = 0;  // the budget alone
    auto built = [&](uint64_t budget, const Camera &camera, std::vector<std::string> &warnings) {
        RenderSceneBuilder builder;
        builder.setGeometryBudget(budget);
        generateCityGml(
            d.cityGml[0], d.georeference, camera, builder, [](const auto &) { return kNoTexture; }, warnings);
        return std::move(builder).build();
    };
    Camera camera;
    std::vector<std::string> none;
    RenderScene whole = built(UINT64_MAX, camera, none);
    ASSERT_EQ(whole.meshes.size(), 2u);
    EXPECT_EQ(buildingsAt(whole, "citygml/file"), 2u);
    // The camera beside the first building: the second is the farther.
    Vec3f first = whole.meshes[0].mesh.positions[0];
    camera.position = first + Vec3f{0, -20, 2};
    camera.lookAt = first;
    // One triangle short of both in full.
    uint64_t budget =
        (whole.meshes[0].mesh.triangleCount() + whole.meshes[1].mesh.triangleCount() - 1) * kBytesPerTriangle;
    std::vector<std::string> warnings;
    RenderScene part = built(budget, camera, warnings);
    EXPECT_EQ(buildingsAt(part, "citygml/file"), 1u);
    EXPECT_EQ(buildingsAt(part, "citygml/box"), 1u);
    ASSERT_EQ(part.meshes.size(), 2u);
    EXPECT_EQ(part.meshes[0].buildingId, whole.meshes[0].buildingId) << "the nearer keeps its model";
    std::string said = fmt::format("{}", fmt::join(warnings, "\n"));
    EXPECT_NE(said.find("geometry budget of 0.0 GB; 1 of them drawn as boxes"), std::string::npos) << said;
}

TEST(CityGmlBuildings, WhatTheSceneLacksIsSaid) {
    std::string box = test::sourceFile("fuzz/corpus/citygml/lod1-box.gml");
    std::string noGeoreference =
        test::inputErrorOf([&] { build(fmt::format("<scene version=\"1\"><citygml file=\"{}\"/></scene>", box)); });
    EXPECT_NE(noGeoreference.find("test.xml:1:20: a <citygml> needs the scene's <georeference>, such as "
                                  "<georeference crs=\"EPSG:25832\" origin=\"500005 5400004\"/>"),
              std::string::npos)
        << noGeoreference;
    std::string disagree = test::inputErrorOf([&] { build(fzkScene(box, " crs=\"EPSG:25833\"")); });
    EXPECT_NE(disagree.find("crs EPSG:25833 disagrees with the file's srsName 'urn:ogc:def:crs:EPSG::25832'"),
              std::string::npos)
        << disagree;
    std::vector<std::string> warnings;
    RenderScene none = build(fzkScene(box, " lod=\"2\""), &warnings);
    EXPECT_TRUE(none.meshes.empty());
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings.back().find("draws nothing: it holds 1 building(s) with no polygon of LoD 2 to 2"),
              std::string::npos)
        << warnings.back();
}

TEST(CityGmlBuildings, CityGmlInTheWrongElementSaysWhereItBelongs) {
    std::string box = test::sourceFile("fuzz/corpus/citygml/lod1-box.gml");
    std::string asCity = test::inputErrorOf([&] {
        build(
            fmt::format("<scene version=\"1\"><city file=\"{}\" rules=\"../rules/gruenderzeit/FacadeStructure.xml\"/>"
                        "</scene>",
                        box));
    });
    EXPECT_NE(asCity.find("this is CityGML, which a scene reads with <citygml file=\"…\"/>"), std::string::npos)
        << asCity;
    std::string asMesh =
        test::inputErrorOf([&] { build(fmt::format("<scene version=\"1\"><mesh file=\"{}\"/></scene>", box)); });
    EXPECT_NE(asMesh.find("a .gml file is no mesh; CityGML buildings come into a scene with <citygml"),
              std::string::npos)
        << asMesh;
}

}  // namespace
}  // namespace veduta
