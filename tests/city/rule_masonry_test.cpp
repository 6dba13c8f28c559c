// Finkenzeller's masonry from rule files (<Masonry>, docs/facades.md): read with the rules, laid on
// the walls a wall model builds on the facades it names, shaded procedurally or baked at the
// camera's texels.
#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/rule_file.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

bool isWrl(std::string_view name) { return name.ends_with(".wrl"); }

std::string bricks() { return test::sourceFile("rules/gruenderzeit/party_wall.bricks"); }

std::string masonryRules(const std::string &masonry) {
    return fmt::format(
        "<Rulefile name=\"t\">\n{}\n<Rule><Predecessor>A</Predecessor><Rules>"
        "<Probability value=\"1\"><Symbol>Wall0.wrl</Symbol></Probability></Rules></Rule>\n"
        "</Rulefile>",
        masonry);
}

std::string errorOf(const std::string &masonry) {
    return test::inputErrorOf([&] { parseRuleFile(masonryRules(masonry), "t.xml", isWrl); });
}

TEST(RuleMasonry, IsReadWithItsFacadesKindAndUnit) {
    RuleSet set = parseRuleFile(
        masonryRules(fmt::format("<Masonry model=\"Wall0.wrl\" facades=\"SideFacade  SmallFacade\" bricks=\"{}\" "
                                 "unit=\"0.01\"/>\n<Masonry model=\"Wall0.wrl\" bricks=\"{}\"/>",
                                 bricks(), bricks())),
        "t.xml", isWrl);
    ASSERT_EQ(set.masonry.size(), 2u);
    const MasonryRule &sides = set.masonry[0];
    EXPECT_EQ(sides.model, "Wall0.wrl");
    EXPECT_EQ(sides.facades, (std::vector<std::string>{"SideFacade", "SmallFacade"}));
    EXPECT_EQ(sides.style.kind, MasonryStyle::Kind::Bricks);
    EXPECT_FLOAT_EQ(float(sides.style.metresPerUnit), 0.01f);
    ASSERT_TRUE(sides.style.bricks);
    EXPECT_EQ(sides.loc.line, 2);
    EXPECT_TRUE(sides.covers("SideFacade"));
    EXPECT_FALSE(sides.covers("FrontFacade"));
    EXPECT_TRUE(set.masonry[1].covers("FrontFacade"));  // no facades=: all
    EXPECT_FLOAT_EQ(float(set.masonry[1].style.metresPerUnit), 1.0f);
}

TEST(RuleMasonry, MistakesAreSaidAtTheElementOrTheFile) {
    EXPECT_NE(errorOf("<Masonry model=\"Wall0.wrl\"/>").find("t.xml:2:1: <Masonry> needs one of bricks="),
              std::string::npos)
        << errorOf("<Masonry model=\"Wall0.wrl\"/>");
    std::string two = errorOf(fmt::format("<Masonry model=\"Wall0.wrl\" bricks=\"{0}\" ashlar=\"{0}\"/>", bricks()));
    EXPECT_NE(two.find("gives both bricks= and ashlar="), std::string::npos) << two;
    std::string missing = errorOf("<Masonry model=\"Wall0.wrl\" bricks=\"no-such.bricks\"/>");
    EXPECT_NE(missing.find("t.xml:2:"), std::string::npos) << missing;
    EXPECT_NE(missing.find("no-such.bricks"), std::string::npos) << missing;
    std::string unit = errorOf(fmt::format("<Masonry model=\"Wall0.wrl\" bricks=\"{}\" unit=\"0\"/>", bricks()));
    EXPECT_NE(unit.find("unit"), std::string::npos) << unit;
    std::string extra = errorOf(fmt::format("<Masonry model=\"Wall0.wrl\" bricks=\"{}\" colour=\"1\"/>", bricks()));
    EXPECT_NE(extra.find("colour"), std::string::npos) << extra;
    // A broken description is said in its own file.
    std::string bond = errorOf(fmt::format("<Masonry model=\"Wall0.wrl\" ashlar=\"{}\"/>", bricks()));
    EXPECT_NE(bond.find("party_wall.bricks:"), std::string::npos) << bond;
}

TEST(RuleMasonry, TheGeneratorRefusesAModelThatIsNoWall) {
    for (const char *model : {"Nothing.wrl", "Cylinder.wrl"}) {
        RuleSet set = parseRuleFile(masonryRules(fmt::format("<Masonry model=\"{}\" bricks=\"{}\"/>", model, bricks())),
                                    "t.xml", isWrl);
        const AssetLibrary &assets = AssetLibrary::builtIn();
        Grammar grammar(set, [&](std::string_view n) { return assets.findTerminal(n); });
        RenderSceneBuilder builder;
        std::string message =
            test::inputErrorOf([&] { BuildingGenerator(grammar, AssetLibrary::builtIn(), builder, 0); });
        EXPECT_NE(message.find("t.xml:2:1: <Masonry model=\""), std::string::npos) << message;
    }
}

// The street, its <render masonry> as given (none: the default).
std::string street(const std::string &rules, const std::string &masonry = "") {
    return fmt::format(R"(<scene version="1"><camera position="7 -25 6" look_at="7 6 8" resolution="320 180"/>
        {}
        <buildings rules="{}" seed="3">
          <building footprint="0 0 14 0 14 12 0 12" street="0"/>
          <building footprint="30 0 44 0 44 12 30 12" street="0"/>
        </buildings></scene>)",
                       masonry.empty() ? "" : fmt::format("<render masonry=\"{}\"/>", masonry),
                       test::sourceFile(rules));
}

// The masonry materials of a scene, and the triangles that show them; baked, their texture
// coordinates lie in the atlas.
size_t masonryTriangles(const RenderScene &scene, bool inAtlas = false) {
    size_t count = 0;
    for (const BakedMesh &baked : scene.meshes)
        for (size_t t = 0; t < baked.mesh.triangleCount(); ++t) {
            const Material &m = scene.materials.at(baked.mesh.triangleMaterials[t]);
            if (m.name.find("masonry)") == std::string::npos) continue;
            EXPECT_NE(m.diffuseMap, kNoTexture);
            EXPECT_NE(m.normalMap, kNoTexture);
            EXPECT_EQ(scene.textures->fingerprint(m.diffuseMap).starts_with("procedural:"), !inAtlas);
            for (int k = 0; inAtlas && k < 3; ++k) {
                Vec2f uv = baked.mesh.uvs[baked.mesh.indices[3 * t + size_t(k)]];
                EXPECT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1) << uv.x << " " << uv.y;
            }
            // The side facades only: their walls face ±x.
            const uint32_t *v = &baked.mesh.indices[3 * t];
            Vec3f n = cross(baked.mesh.positions[v[1]] - baked.mesh.positions[v[0]],
                            baked.mesh.positions[v[2]] - baked.mesh.positions[v[0]]);
            EXPECT_GT(std::abs(n.x), 0.99f * length(n)) << n.x << " " << n.y << " " << n.z;
            ++count;
        }
    return count;
}

TEST(RuleMasonry, TheBrickRulesLayMasonryOnTheSidesAndNowhereElse) {
    std::vector<std::string> warnings;
    RenderScene brick = buildRenderScene(
        readSceneText(street("rules/gruenderzeit/FacadeStructureBrick.xml"), "test.xml", test::testData()), &warnings);
    ASSERT_TRUE(brick.textures);
    size_t shaded = masonryTriangles(brick);
    EXPECT_GT(shaded, 0u);
    // Baked into an atlas instead, the same walls show it.
    RenderScene atlas = buildRenderScene(
        readSceneText(street("rules/gruenderzeit/FacadeStructureBrick.xml", "baked"), "test.xml", test::testData()));
    EXPECT_EQ(masonryTriangles(atlas, true), shaded);
    RenderScene plain =
        buildRenderScene(readSceneText(street("rules/gruenderzeit/FacadeStructure.xml"), "test.xml", test::testData()));
    EXPECT_EQ(masonryTriangles(plain), 0u);
    // The same geometry: masonry changes the walls' maps, not their shape.
    size_t brickTriangles = 0, plainTriangles = 0;
    for (const BakedMesh &b : brick.meshes) brickTriangles += b.mesh.triangleCount();
    for (const BakedMesh &b : plain.meshes) plainTriangles += b.mesh.triangleCount();
    EXPECT_EQ(brickTriangles, plainTriangles);
}

TEST(RuleMasonry, WithoutACameraTheWallsKeepTheirTextureAndOneWarningSaysSo) {
    BuildingRules loaded(test::sourceFile("rules/gruenderzeit/FacadeStructureBrick.xml"));
    RenderSceneBuilder builder;
    builder.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
    BuildingGenerator generator(loaded.grammar, AssetLibrary::builtIn(), builder, 0);
    std::vector<std::string> warnings;
    for (int i = 0; i < 2; ++i) {
        BuildingSpec spec;
        spec.id = uint32_t(i + 1);
        spec.footprint.points = {{0, 0}, {14, 0}, {14, 12}, {0, 12}};
        spec.footprint.streetEdges = {true, false, false, false};
        spec.settings = SettingsStack({&loaded.rules.settings, &defaultBuildingSettings()});
        generator.generate(spec, warnings);
    }
    size_t said = 0;
    for (const std::string &w : warnings) said += w.find("no camera to bake masonry for") != std::string::npos;
    EXPECT_EQ(said, 1u);
    RenderScene scene = std::move(builder).build();
    EXPECT_EQ(masonryTriangles(scene), 0u);
}

}  // namespace
}  // namespace veduta
