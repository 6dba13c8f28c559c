// Cornices from rule files (<Cornice>, docs/facades.md): read with the rules, the model's places
// taken out of the instances, joined into runs round the corners and swept with the profile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/rule_cornices.h"
#include "city/rule_file.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

bool isWrl(std::string_view name) { return name.ends_with(".wrl"); }

std::string mainCornice() { return test::sourceFile("rules/gruenderzeit/main.cornice"); }

// Every facade: a wall under a 0.45 m strip of the Kranzleiste model.
std::string corniceRules(const std::string &cornice) {
    std::string rules;
    for (const char *facade : {"FrontFacade", "Facade", "SideFacade", "BackFacade", "SmallFacade"})
        rules += fmt::format(
            "<Rule><Predecessor>{}</Predecessor><Rules><Probability value=\"1\"><Split axis=\"u\"/>"
            "<Symbol size=\"1r\">Wall0.wrl</Symbol><Symbol size=\"0.45\">Cornice6Kranzleiste.wrl</Symbol>"
            "</Probability></Rules></Rule>\n",
            facade);
    return fmt::format("<Rulefile name=\"t\">\n{}\n{}</Rulefile>", cornice, rules);
}

std::string errorOf(const std::string &cornice) {
    return test::inputErrorOf([&] { parseRuleFile(corniceRules(cornice), "t.xml", isWrl); });
}

TEST(RuleCornice, IsReadWithItsModelRulesAndProfile) {
    RuleSet set = parseRuleFile(
        corniceRules(fmt::format(
            "<Cornice model=\"Cornice6Kranzleiste.wrl\" rules=\" FrontFacade  SideFacade\" profile=\"{}\"/>",
            mainCornice())),
        "t.xml", isWrl);
    ASSERT_EQ(set.cornices.size(), 1u);
    const CorniceRule &rule = set.cornices[0];
    EXPECT_EQ(rule.model, "Cornice6Kranzleiste.wrl");
    EXPECT_EQ(rule.rules, (std::vector<std::string>{"FrontFacade", "SideFacade"}));
    ASSERT_TRUE(rule.cornice);
    EXPECT_FALSE(rule.cornice->profile.commands.empty());
    EXPECT_EQ(rule.cornice->consoles.size(), 1u);
    EXPECT_EQ(rule.directory, std::filesystem::path(mainCornice()).parent_path());
    EXPECT_EQ(rule.loc.line, 2);
}

TEST(RuleCornice, MistakesAreSaidAtTheElementOrTheProfileFile) {
    auto expectSaid = [](const std::string &cornice, const std::string &said) {
        std::string message = errorOf(cornice);
        EXPECT_NE(message.find(said), std::string::npos) << message;
    };
    expectSaid("<Cornice model=\"Cornice6Kranzleiste.wrl\"/>", "t.xml:2:");
    expectSaid("<Cornice model=\"Cornice6Kranzleiste.wrl\"/>", "profile");
    expectSaid("<Cornice model=\"Cornice6Kranzleiste.wrl\" profile=\"no-such.cornice\"/>", "no-such.cornice");
    expectSaid(fmt::format("<Cornice model=\"Nothing\" profile=\"{}\"/>", mainCornice()),
               "t.xml:2:1: <Cornice model=\"Nothing\">: no such model");
    expectSaid(fmt::format("<Cornice model=\"Cornice6Kranzleiste.wrl\" rules=\"Roof\" profile=\"{}\"/>", mainCornice()),
               "no rule derives 'Roof'");
    expectSaid(fmt::format("<Cornice model=\"Cornice6Kranzleiste.wrl\" profile=\"{}\" depth=\"1\"/>", mainCornice()),
               "depth");
    // A broken description is said in its own file.
    expectSaid(fmt::format("<Cornice model=\"Cornice6Kranzleiste.wrl\" profile=\"{}\"/>",
                           test::sourceFile("rules/gruenderzeit/party_wall.bricks")),
               "party_wall.bricks:");
}

TEST(RuleCornice, TheGeneratorRefusesAWallModel) {
    RuleSet set = parseRuleFile(
        corniceRules(fmt::format("<Cornice model=\"Wall0.wrl\" profile=\"{}\"/>", mainCornice())), "t.xml", isWrl);
    const AssetLibrary &assets = AssetLibrary::builtIn();
    Grammar grammar(set, [&](std::string_view n) { return assets.findTerminal(n); });
    RenderSceneBuilder builder;
    std::string message = test::inputErrorOf([&] { BuildingGenerator(grammar, assets, builder, 0); });
    EXPECT_NE(message.find("t.xml:2:1: <Cornice model=\"Wall0.wrl\">: a wall model"), std::string::npos) << message;
}

// --- joining places into runs ------------------------------------------------------------------

struct Box {
    Vec3f low{INFINITY}, high{-INFINITY};
};

Box boxOf(const Mesh &mesh) {
    Box box;
    for (const Vec3f &p : mesh.positions)
        for (int k = 0; k < 3; ++k) {
            box.low[k] = std::min(box.low[k], p[k]);
            box.high[k] = std::max(box.high[k], p[k]);
        }
    return box;
}

class CorniceRuns : public ::testing::Test {
  protected:
    CorniceRuns() {
        rule.cornice = std::make_shared<const CorniceDescription>(parseCorniceDescription(
            "Modifications { line, rel, 90, 0.5; line, rel, -90, 1; line, rel, -90, 0.5; }", "box.cornice"));
        footprint.points = {{0, 0}, {14, 0}, {14, 12}, {0, 12}};
        footprint.streetEdges = {true, false, false, false};
        facades = makeStartShapes(footprint, 10);
    }

    // The place of the top 0.5 m of facade f from `left` to `right` metres (all of it by default).
    CornicePlace top(size_t f, double left = 0, double right = -1) const {
        return {&rule, f, left, right < 0 ? facades[f].width : right, 9.5, 10, 3};
    }

    CorniceRule rule;
    Footprint footprint;
    std::vector<StartShape> facades;
};

TEST_F(CorniceRuns, PlacesRoundTheWholeBuildingAreOneMitredRing) {
    CorniceRun ring = sweepRuleCornices({top(0), top(1), top(2), top(3)}, facades);
    // The box profile, half as deep as high, reaches 0.25 m out of the 0.5 m band: a mitred
    // ring's outermost points stand on the bisectors, 0.25 m out of both walls at every corner.
    Box box = boxOf(ring.mesh);
    EXPECT_NEAR(box.low.x, -0.25, 1e-5);
    EXPECT_NEAR(box.low.y, -0.25, 1e-5);
    EXPECT_NEAR(box.high.x, 14.25, 1e-5);
    EXPECT_NEAR(box.high.y, 12.25, 1e-5);
    EXPECT_NEAR(box.low.z, 9.5, 1e-5);
    EXPECT_NEAR(box.high.z, 10, 1e-5);
    for (Vec2f corner : {Vec2f{-0.25f, -0.25f}, Vec2f{14.25f, -0.25f}, Vec2f{14.25f, 12.25f}, Vec2f{-0.25f, 12.25f}}) {
        bool found = std::any_of(ring.mesh.positions.begin(), ring.mesh.positions.end(), [&](const Vec3f &p) {
            return std::abs(p.x - corner.x) < 1e-5f && std::abs(p.y - corner.y) < 1e-5f;
        });
        EXPECT_TRUE(found) << corner.x << " " << corner.y;
    }
    // A ring has no ends to cap: the same places swept as one closed path give the same mesh.
    std::vector<Vec2d> outline;
    for (Vec2f p : footprint.points) outline.push_back({p.x, p.y});
    CorniceRun expected =
        buildCorniceRun(*rule.cornice, sweepPathThrough(outline, 9.5, true, OutwardSide::Right), 0.5, 3);
    EXPECT_EQ(ring.mesh.triangleCount(), expected.mesh.triangleCount());
    for (MaterialId m : ring.mesh.triangleMaterials) EXPECT_EQ(m, 3u);
}

TEST_F(CorniceRuns, PiecesThatTouchAreOneRunAndAGapMakesTwo) {
    CorniceRun whole = sweepRuleCornices({top(0)}, facades);
    CorniceRun touching = sweepRuleCornices({top(0, 7, 14), top(0, 0, 7)}, facades);
    CorniceRun gap = sweepRuleCornices({top(0, 0, 5), top(0, 8, 14)}, facades);
    EXPECT_EQ(touching.mesh.triangleCount(), whole.mesh.triangleCount());
    EXPECT_EQ(gap.mesh.triangleCount(), 2 * whole.mesh.triangleCount());
    Box box = boxOf(whole.mesh);
    EXPECT_NEAR(box.low.x, 0, 1e-5);
    EXPECT_NEAR(box.high.x, 14, 1e-5);
    EXPECT_NEAR(box.low.y, -0.25, 1e-5);  // out of the front, which faces −y
    EXPECT_NEAR(box.high.y, 0, 1e-5);
    // Nothing of the gap's two runs lies in the gap.
    for (const Vec3f &p : gap.mesh.positions) EXPECT_TRUE(p.x <= 5 + 1e-5f || p.x >= 8 - 1e-5f) << p.x;
}

TEST_F(CorniceRuns, AnOpenRunTurnsTheCornerMitredAndBandsAtOtherHeightsStayApart) {
    CorniceRun corner = sweepRuleCornices({top(0), top(1)}, facades);
    CorniceRun two = sweepRuleCornices({top(0)}, facades), one = sweepRuleCornices({top(1)}, facades);
    // One run round the corner: its mitre point stands on the bisector, and it has fewer
    // triangles than two runs (two caps fewer).
    bool mitred = std::any_of(corner.mesh.positions.begin(), corner.mesh.positions.end(), [](const Vec3f &p) {
        return std::abs(p.x - 14.25f) < 1e-5f && std::abs(p.y + 0.25f) < 1e-5f;
    });
    EXPECT_TRUE(mitred);
    EXPECT_LT(corner.mesh.triangleCount(), two.mesh.triangleCount() + one.mesh.triangleCount());
    CornicePlace lower = top(1);
    lower.bottom = 5;
    lower.top = 5.5;
    CorniceRun apart = sweepRuleCornices({top(0), lower}, facades);
    EXPECT_EQ(apart.mesh.triangleCount(), two.mesh.triangleCount() + one.mesh.triangleCount());
}

// --- through the generator ---------------------------------------------------------------------

struct Made {
    BuildingGenerator::MadeBuilding building;
    size_t kranzleisten = 0;  // instances of the model
};

Made makeBuilding(const std::string &cornice) {
    RuleSet set = parseRuleFile(corniceRules(cornice), "t.xml", isWrl);
    const AssetLibrary &assets = AssetLibrary::builtIn();
    Grammar grammar(set, [&](std::string_view n) { return assets.findTerminal(n); });
    RenderSceneBuilder builder;
    builder.addMaterial(Material::lambertian("default", Vec3f(0.8f)));
    BuildingGenerator generator(grammar, assets, builder, 0);
    BuildingSpec spec;
    spec.id = 1;
    spec.footprint.points = {{0, 0}, {14, 0}, {14, 12}, {0, 12}};
    spec.footprint.streetEdges = {true, false, false, false};
    spec.settings = SettingsStack({&set.settings, &defaultBuildingSettings()});
    std::vector<std::string> warnings;
    Made made{generator.make(spec, warnings)};
    uint32_t model = *assets.find("Cornice6Kranzleiste");
    for (const auto &placement : made.building.instances) made.kranzleisten += placement.prototype.model == model;
    return made;
}

TEST(RuleCornice, TheModelsPlacesBecomeASweepWithConsoles) {
    Made models = makeBuilding("");
    Made swept =
        makeBuilding(fmt::format("<Cornice model=\"Cornice6Kranzleiste.wrl\" profile=\"{}\"/>", mainCornice()));
    EXPECT_EQ(models.kranzleisten, 4u);  // one a facade
    EXPECT_EQ(swept.kranzleisten, 0u);
    EXPECT_GT(swept.building.mesh.triangleCount(), models.building.mesh.triangleCount());
    EXPECT_TRUE(models.building.consoles.empty());
    ASSERT_EQ(swept.building.consoles.size(), 1u);
    const ConsoleSet &consoles = swept.building.consoles[0];
    EXPECT_EQ(consoles.objectFile, (std::filesystem::path(mainCornice()).parent_path() / "console.obj").string());
    // main.cornice sets one every 0.6 m: 52 m of outline, less the corners' margins.
    EXPECT_GE(consoles.transforms.size(), 80u);
    EXPECT_LE(consoles.transforms.size(), 90u);
    // Each stands under the corona, as deep as the profile reaches (about 0.45 m; once the
    // profile's own units, 41 m).
    for (const Transform &t : consoles.transforms) {
        double depth = length(t.applyVector({0, 0, 1}));
        EXPECT_NEAR(depth, 41 * 0.45 / 41.392, 1e-3);
    }
}

TEST(RuleCornice, OnlyThePlacesOfItsRulesAreTaken) {
    Made front = makeBuilding(fmt::format(
        "<Cornice model=\"Cornice6Kranzleiste.wrl\" rules=\"FrontFacade\" profile=\"{}\"/>", mainCornice()));
    EXPECT_EQ(front.kranzleisten, 3u);  // the other three facades keep the model
}

}  // namespace
}  // namespace veduta
