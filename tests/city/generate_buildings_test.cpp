// <buildings> in scene files: read, generated into the render scene, and their errors at
// their place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "assembly/build_scene.h"
#include "city/generate_buildings.h"
#include "city/plinth.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

std::string rules() { return test::sourceFile("rules/gruenderzeit/FacadeStructure.xml"); }

std::string scene(const std::string &buildings) {
    return "<scene version=\"1\">\n<buildings rules=\"" + rules() + "\">\n" + buildings + "</buildings>\n</scene>\n";
}

RenderScene build(const std::string &xml, std::vector<std::string> *warnings = nullptr) {
    return buildRenderScene(readSceneText(xml, "test.xml", test::testData()), warnings);
}

std::string errorOf(const std::string &xml) {
    return test::inputErrorOf([&] { build(xml); });
}

TEST(GenerateBuildings, BuildingsAndFacadesBecomeGeometryWithTheirIds) {
    std::vector<std::string> warnings;
    RenderScene s = build(scene("<building footprint=\"0 0 14 0 14 12 0 12\" street=\"0\"/>\n"
                                "<building id=\"9\" footprint=\"14 0 30 0 30 12 14 12\" street=\"0\">"
                                "<BuildingSettings><BuildingHeight>20</BuildingHeight></BuildingSettings></building>\n"
                                "<facade start=\"FrontFacade\" width=\"10\" height=\"14\" translate=\"0 -30 0\"/>\n"),
                          &warnings);
    ASSERT_EQ(s.meshes.size(), 3u);
    EXPECT_EQ(s.meshes[0].buildingId, 1u);  // unnumbered: the smallest free ids in file order
    EXPECT_EQ(s.meshes[1].buildingId, 9u);
    EXPECT_EQ(s.meshes[2].buildingId, 2u);
    float top = 0;
    for (const Vec3f &p : s.meshes[1].mesh.positions) top = std::max(top, p.z);
    EXPECT_GT(top, 20 + 3);  // the lot's own height, with its roof
    EXPECT_FALSE(s.instances.empty());
    ASSERT_EQ(warnings.size(), 1u);  // Bilke's own rule whose probabilities sum to 0.5
    EXPECT_NE(warnings[0].find("sum to 0.5"), std::string::npos) << warnings[0];
}

TEST(GenerateBuildings, SettingsOfTheGroupComeBetweenTheBuildingsAndTheDefaults) {
    // The defaults say 15 m walls and a 4 m roof; the group 12 m; the second building 18 m.
    std::string xml = "<scene version=\"1\">\n<buildings rules=\"" + rules() +
        "\">\n<BuildingSettings><BuildingHeight>12</BuildingHeight></BuildingSettings>\n"
        "<building footprint=\"0 0 14 0 14 12 0 12\" street=\"0\"/>\n"
        "<building footprint=\"20 0 34 0 34 12 20 12\" street=\"0\"><BuildingSettings>"
        "<BuildingHeight>18</BuildingHeight></BuildingSettings></building>\n</buildings>\n</scene>\n";
    RenderScene s = build(xml);
    auto top = [&](size_t mesh) {
        float z = 0;
        for (const Vec3f &p : s.meshes[mesh].mesh.positions) z = std::max(z, p.z);
        return z;
    };
    EXPECT_NEAR(top(0), 12 + 4, 1e-3);  // the ridge of the gable
    EXPECT_NEAR(top(1), 18 + 4, 1e-3);
}

TEST(GenerateBuildings, AClockwiseFootprintIsTurnedRoundWithAWarning) {
    std::vector<std::string> warnings;
    build(scene("<building footprint=\"0 12 14 12 14 0 0 0\" street=\"2\"/>\n"), &warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[1].find("test.xml:3:"), std::string::npos) << warnings[1];
}

TEST(GenerateBuildings, ErrorsAreAtTheirPlace) {
    EXPECT_NE(errorOf(scene("<building footprint=\"0 0 14 0 14\"/>\n"))
                  .find("test.xml:3:22: a footprint is at least "
                        "three x y pairs"),
              std::string::npos);
    EXPECT_NE(errorOf(scene("<building footprint=\"0 0 14 0 14 12 0 12\" street=\"4\"/>\n"))
                  .find("test.xml:3:51: street edges are numbers of footprint edges, 0 to 3"),
              std::string::npos);
    EXPECT_NE(errorOf(scene("<building footprint=\"0 0 14 0 0 12 14 12\"/>\n")).find("test.xml:3:"),
              std::string::npos);  // crosses itself
    EXPECT_NE(errorOf(scene("<building id=\"2\" footprint=\"0 0 1 0 1 1\"/>\n<building id=\"2\" "
                            "footprint=\"0 0 1 0 1 1\"/>\n"))
                  .find("test.xml:4:1: building id 2 is already used at test.xml:3:1"),
              std::string::npos);
    EXPECT_NE(errorOf(scene("<house/>\n")).find("test.xml:3:1: <house> cannot stand inside <buildings>"),
              std::string::npos);
    EXPECT_NE(errorOf(scene("<facade start=\"Nowhere\" width=\"5\" height=\"5\"/>\n"))
                  .find("test.xml:3:1: the rule file has no rule for the start symbol 'Nowhere'"),
              std::string::npos);
    EXPECT_NE(errorOf(scene("<building footprint=\"0 0 9 0 9 9 0 9\"><BuildingSettings><FloorHeight>tall"
                            "</FloorHeight></BuildingSettings></building>\n"))
                  .find("setting FloorHeight must be a number, not 'tall'"),
              std::string::npos);
    std::string missing = "<scene version=\"1\"><buildings rules=\"nowhere.xml\"/></scene>";
    EXPECT_NE(errorOf(missing).find("test.xml:1:38: cannot read the rule file"), std::string::npos) << errorOf(missing);
}

// A derivation limit is hit by a building's size more often than by its rules: the error
// names the building, the rule and the facade.
TEST(GenerateBuildings, ABuildingTooLargeForTheDerivationLimitsIsNamed) {
    std::string error = errorOf(scene("<building footprint=\"0 0 30000 0 30000 12 0 12\"/>\n"));
    EXPECT_EQ(error.rfind("test.xml:3:1: this building cannot be built: " + rules() + ":", 0), 0u) << error;
    EXPECT_NE(error.find("makes more than 200000 shapes"), std::string::npos) << error;
    EXPECT_NE(error.find("(on a facade 30000 m wide and "), std::string::npos) << error;
}

TEST(GenerateBuildings, ABadRuleFileIsAnErrorInThatFile) {
    std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("veduta_bad_rules_" + std::to_string(::getpid()) + ".xml");
    std::ofstream(file) << "<Rulefile name=\"bad\">\n<Rule><Predecessor>FrontFacade</Predecessor><Rules>\n"
                           "<Probability value=\"1\"><Symbol>Nothing</Symbol></Probability>\n</Rules></Rule>\n"
                           "</Rulefile>\n";
    std::string xml = "<scene version=\"1\"><buildings rules=\"" + file.string() +
        "\"><building footprint=\"0 0 9 0 9 9 0 9\"/></buildings></scene>";
    std::string error = errorOf(xml);
    EXPECT_NE(error.find(file.string() + ":3:"), std::string::npos) << error;
    EXPECT_NE(error.find("unknown symbol 'Nothing'"), std::string::npos) << error;
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace veduta

namespace veduta {
namespace {

// A ground that slopes along x, with the footprint's corner (0, 0) lowest: the building stands
// on the height the ground function gives, and a plinth reaches below it.
TEST(GenerateBuildings, ABuildingWithoutBaseStandsOnTheGroundOverAPlinth) {
    SceneDescription d =
        readSceneText(scene("<building footprint=\"0 0 14 0 14 12 0 12\" street=\"0\"/>\n"
                            "<building base=\"3\" footprint=\"20 0 34 0 34 12 20 12\" street=\"0\"/>\n"),
                      "test.xml", test::testData());
    std::vector<Vec2f> asked;
    GroundHeight ground = [&](const std::vector<Vec2f> &footprint) {
        asked = footprint;
        return std::optional<float>(42.5f);
    };
    RenderSceneBuilder builder;
    builder.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
    std::vector<std::string> warnings;
    generateBuildings(d.buildingGroups[0], 0, ground, builder, warnings);
    RenderScene s = std::move(builder).build();
    EXPECT_EQ(asked.size(), 4u);  // only the building without a base of its own asked
    MaterialId plinth = kNoMaterial;
    for (MaterialId m = 0; m < s.materials.size(); ++m)
        if (s.materials[m].name == "plinth") plinth = m;
    ASSERT_NE(plinth, kNoMaterial);
    float lowestWall = 1e9f, lowestPlinth = 1e9f, highestPlinth = -1e9f, lowestOther = 1e9f;
    for (const BakedMesh &baked : s.meshes) {
        const Mesh &m = baked.mesh;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) {
                const Vec3f &p = m.positions[m.indices[3 * t + k]];
                if (m.triangleMaterials[t] == plinth) {
                    lowestPlinth = std::min(lowestPlinth, p.z);
                    highestPlinth = std::max(highestPlinth, p.z);
                } else if (p.x < 17) {
                    lowestWall = std::min(lowestWall, p.z);
                } else {
                    lowestOther = std::min(lowestOther, p.z);
                }
            }
        }
    }
    EXPECT_FLOAT_EQ(lowestWall, 42.5f);
    EXPECT_FLOAT_EQ(highestPlinth, 42.5f);
    EXPECT_FLOAT_EQ(lowestPlinth, 42.5f - kPlinthDepth);
    EXPECT_FLOAT_EQ(lowestOther, 3.0f);  // its own base, and no plinth
}

}  // namespace
}  // namespace veduta
