// Bilke's golden tests of the split grammar (Bilke 2009 (digest §10)): T1 split, T2 repeat, T3 mixed
// sizes, T4 scale inheritance, T5 branch frequencies and per-building consistency, T6 settings
// precedence; and the derivation's limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "city/building_settings.h"
#include "city/derivation.h"
#include "city/listing_2_2.h"
#include "city/rule_file.h"

namespace veduta {
namespace {

// Terminal names of the tests: whatever no rule derives is a model, numbered by first sight.
class TestModels {
  public:
    std::optional<uint32_t> index(std::string_view name) {
        auto it = std::find(names_.begin(), names_.end(), name);
        if (it != names_.end()) return uint32_t(it - names_.begin());
        names_.emplace_back(name);
        return uint32_t(names_.size() - 1);
    }
    const std::string &name(uint32_t i) const { return names_[i]; }

  private:
    std::vector<std::string> names_;
};

SettingValue number(float v) { return {std::to_string(v), v, FileLoc{"test", 0, 0}}; }

struct Fixture {
    RuleSet rules;
    TestModels models;
    std::unique_ptr<Grammar> grammar;
    SettingsMap settings;
    SettingsStack stack;
    std::vector<std::string> warnings;

    explicit Fixture(const std::string &xml, std::vector<std::pair<std::string, float>> values = {}) {
        // Listing 2.2's leaves are models here, as the parser's tests have it.
        rules = parseRuleFile(xml, "test.xml", [](std::string_view n) {
            return n.ends_with(".wrl") || n == "WeitereEtagen" || n == "Fassadenelement";
        });
        grammar = std::make_unique<Grammar>(rules, [this](std::string_view n) { return models.index(n); });
        for (auto &[name, value] : values) settings[name] = number(value);
        stack = SettingsStack({&settings, &rules.settings, &defaultBuildingSettings()});
    }

    std::vector<Terminal> derive(const std::string &start, Vec2f size, uint32_t building = 1, uint32_t seed = 7) {
        BuildingHeights heights = randomiseHeights(stack, seed, building);
        BuildingProperties properties(stack, heights);
        std::vector<Terminal> out;
        deriveFacade(*grammar, start, size, properties, {seed, building}, out, warnings);
        return out;
    }
    const std::string &name(const Terminal &t) const { return models.name(t.model); }
};

Vec3f centre(const Terminal &t) { return t.shapeToFacade.applyPoint({0, 0, 0}); }

TEST(Derivation, T1SplitGivesAbsoluteSizesFirstAndSharesTheRest) {
    Fixture f(kListing22);
    auto out = f.derive("Fassade1", {10, 15});
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(f.name(out[0]), "Bodenetage.wrl");
    EXPECT_FLOAT_EQ(out[0].size.y, 4);
    EXPECT_FLOAT_EQ(out[0].size.x, 10);
    EXPECT_NEAR(centre(out[0]).y, 2, 1e-5);
    EXPECT_NEAR(centre(out[0]).x, 5, 1e-5);
    ASSERT_NE(out[0].texture, nullptr);
    EXPECT_EQ(*out[0].texture, "Bodenetage.jpg");
    EXPECT_EQ(f.name(out[1]), "WeitereEtagen");
    EXPECT_FLOAT_EQ(out[1].size.y, 11);
    EXPECT_NEAR(centre(out[1]).y, 9.5, 1e-5);
    EXPECT_TRUE(f.warnings.empty());
}

TEST(Derivation, T2RepeatTakesTheFloorOfTheCountAndStretchesTheTiles) {
    Fixture f(kListing22, {{"FassadenelementBreite", 1.5f}});
    auto out = f.derive("Fassade2", {10, 15});
    ASSERT_EQ(out.size(), 6u);
    for (size_t i = 0; i < out.size(); ++i) {
        EXPECT_NEAR(out[i].size.x, 10.0 / 6, 1e-5);
        EXPECT_NEAR(centre(out[i]).x, (i + 0.5) * 10.0 / 6, 1e-4);
    }

    Fixture floors(R"(<Rulefile name="t"><Rule><Predecessor>Floors</Predecessor><Rules>
      <Probability value="1"><Repeat axis="u" size="1"/><Symbol property="FloorHeight">Floor.wrl</Symbol></Probability>
      </Rules></Rule></Rulefile>)",
                   {{"FloorHeight", 3}});
    auto rows = floors.derive("Floors", {12, 11});
    ASSERT_EQ(rows.size(), 3u);
    for (const Terminal &t : rows) EXPECT_NEAR(t.size.y, 11.0 / 3, 1e-5);
    // Exact multiples are not lost to rounding: 9 m of 3 m floors are three.
    EXPECT_EQ(floors.derive("Floors", {12, 9}).size(), 3u);
    // Shorter than one tile: one tile of the scope's own length.
    auto one = floors.derive("Floors", {12, 2});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_FLOAT_EQ(one[0].size.y, 2);
}

TEST(Derivation, FloatingRepeatTakesTheCountWhoseTileIsClosest) {
    Fixture f(R"(<Rulefile name="t"><Rule><Predecessor>Row</Predecessor><Rules>
      <Probability value="1"><Repeat axis="r" size="~2.1"/><Symbol>Tile.wrl</Symbol></Probability>
      </Rules></Rule></Rulefile>)");
    auto out = f.derive("Row", {10, 3});
    ASSERT_EQ(out.size(), 5u);  // CGA's example: 10 m at ~2.1 → five tiles of 2 m
    EXPECT_FLOAT_EQ(out[0].size.x, 2);
    EXPECT_EQ(f.derive("Row", {11, 3}).size(), 5u);     // 2.2 is closer to 2.1 than 1.83
    EXPECT_EQ(f.derive("Row", {11.9f, 3}).size(), 6u);  // 1.98 is closer than 2.38
    EXPECT_EQ(f.derive("Row", {1, 3}).size(), 1u);      // shorter than a tile: one
}

const char *kTiles = R"(<Rulefile name="t">
  <Rule><Predecessor>GroundfloorWindowTileChoice</Predecessor><Rules>
    <Probability value="1"><Split axis="r"/>
      <Symbol size="1r">Wall0.wrl</Symbol>
      <Symbol size="1" property="GroundfloorWindowWidth">Window.wrl</Symbol>
      <Symbol size="1r">Wall0.wrl</Symbol></Probability></Rules></Rule>
  <Rule><Predecessor>FloorTileWindowXPlacement</Predecessor><Rules>
    <Probability value="1"><Split axis="r"/>
      <Symbol size="1r">Wall0.wrl</Symbol>
      <Symbol size="2">Window.wrl</Symbol>
      <Symbol size="1r">Wall0.wrl</Symbol></Probability></Rules></Rule>
  <Rule><Predecessor>FloorTileChoice</Predecessor><Rules>
    <Probability value="1"><Split axis="u"/>
      <Symbol size="1r">Wall0.wrl</Symbol>
      <Symbol size="2r">Window.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)";

std::vector<float> extents(const std::vector<Terminal> &out, int axis) {
    std::vector<float> result;
    for (const Terminal &t : out) result.push_back(axis == 0 ? t.size.x : t.size.y);
    return result;
}

TEST(Derivation, T3MixedAbsoluteAndRelativeSizes) {
    Fixture f(kTiles, {{"GroundfloorWindowWidth", 1.2f}});
    auto a = extents(f.derive("GroundfloorWindowTileChoice", {3, 3}), 0);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_NEAR(a[0], 0.9, 1e-5);
    EXPECT_NEAR(a[1], 1.2, 1e-5);
    EXPECT_NEAR(a[2], 0.9, 1e-5);
    auto b = extents(f.derive("FloorTileWindowXPlacement", {3, 3}), 0);
    EXPECT_NEAR(b[0], 0.5, 1e-5);
    EXPECT_NEAR(b[1], 2, 1e-5);
    EXPECT_NEAR(b[2], 0.5, 1e-5);
    auto c = extents(f.derive("FloorTileChoice", {3, 3}), 1);
    EXPECT_NEAR(c[0], 1, 1e-5);
    EXPECT_NEAR(c[1], 2, 1e-5);
}

TEST(Derivation, OverflowingAbsoluteSizesWarnOnceAndOverlap) {
    Fixture f(kTiles, {{"GroundfloorWindowWidth", 5}});
    auto a = f.derive("GroundfloorWindowTileChoice", {3, 3});
    f.derive("GroundfloorWindowTileChoice", {3, 3});
    ASSERT_EQ(a.size(), 1u);  // the relative walls have no room left
    EXPECT_FLOAT_EQ(a[0].size.x, 5);
    EXPECT_NEAR(centre(a[0]).x, 2.5, 1e-5);
    ASSERT_EQ(f.warnings.size(), 2u);  // once per derivation, not once per shape
    EXPECT_NE(f.warnings[0].find("test.xml:3:"), std::string::npos) << f.warnings[0];
    EXPECT_NE(f.warnings[0].find("exceed"), std::string::npos);
}

TEST(Derivation, T4ScalePropagatesToDescendants) {
    Fixture f(R"(<Rulefile name="t">
      <Rule><Predecessor>WindowPlace</Predecessor><Rules><Probability value="1"><Split axis="u"/>
        <Symbol size="1r">Window.wrl</Symbol>
        <Symbol size="0.2" scale="1.1 1 1">SmallRoofChoice</Symbol></Probability></Rules></Rule>
      <Rule><Predecessor>SmallRoofChoice</Predecessor><Rules><Probability value="1">
        <Symbol>SmallRoofArc.wrl</Symbol>
        <Symbol scale="0.9091 1 1">Wall0.wrl</Symbol></Probability></Rules></Rule>
    </Rulefile>)");
    auto out = f.derive("WindowPlace", {1.2f, 2.5f});
    ASSERT_EQ(out.size(), 3u);
    const Terminal &arc = out[1], &wall = out[2];
    EXPECT_EQ(f.name(arc), "SmallRoofArc.wrl");
    EXPECT_EQ(f.name(wall), "Wall0.wrl");
    EXPECT_NEAR(arc.shapeToFacade.m[0], 1.1, 1e-6);
    EXPECT_NEAR(wall.shapeToFacade.m[0], 1.1 * 0.9091, 1e-5);  // ≈ 1.0
    EXPECT_FLOAT_EQ(wall.size.x, 1.2f);                        // scopes are not scaled
    // Scaling happens about the scope's centre, so the roof stays centred over the window.
    EXPECT_NEAR(centre(arc).x, 0.6, 1e-6);
    EXPECT_NEAR(centre(arc).y, 2.4, 1e-5);
}

TEST(Derivation, TranslateMovesInTheParentsScaledFrameAndAttributesAreInherited) {
    Fixture f(R"(<Rulefile name="t">
      <Rule><Predecessor>Tile</Predecessor><Rules><Probability value="1">
        <Symbol scale="2 1 1" texture="wall\stucco1.png" uv="0.5 0.5" z_scale="right">Inner</Symbol></Probability></Rules></Rule>
      <Rule><Predecessor>Inner</Predecessor><Rules><Probability value="1">
        <Symbol translate="0.5 0 -0.2">Glass0.wrl</Symbol>
        <Symbol texture="reflection\zinc.png" z_scale="none">Bar.wrl</Symbol></Probability></Rules></Rule>
    </Rulefile>)");
    auto out = f.derive("Tile", {2, 3});
    ASSERT_EQ(out.size(), 2u);
    Vec3f glass = centre(out[0]);
    EXPECT_NEAR(glass.x, 1 + 2 * 0.5, 1e-6);  // the translation is scaled by the parent's 2
    EXPECT_NEAR(glass.z, -0.2, 1e-6);
    ASSERT_NE(out[0].texture, nullptr);
    EXPECT_EQ(*out[0].texture, "wall/stucco1.png");
    EXPECT_FLOAT_EQ(out[0].uv.x, 0.5f);
    EXPECT_EQ(out[0].zScale, ZScale::Right);
    EXPECT_EQ(*out[1].texture, "reflection/zinc.png");
    EXPECT_EQ(out[1].zScale, ZScale::None);
}

const char *kCornices = R"(<Rulefile name="t">
  <Rule><Predecessor>Facade</Predecessor><Rules><Probability value="1">
    <Repeat axis="u" size="3"/><Symbol>Floor</Symbol></Probability></Rules></Rule>
  <Rule><Predecessor>Floor</Predecessor><Rules><Probability value="1">
    <Repeat axis="r" size="3"/><Symbol>CorniceChoice</Symbol></Probability></Rules></Rule>
  <Rule><Predecessor>CorniceChoice</Predecessor><Rules>
    <Probability value="0.2"><Symbol>Cornice1.wrl</Symbol></Probability>
    <Probability value="0.2"><Symbol>Cornice2Chamfer.wrl</Symbol></Probability>
    <Probability value="0.2"><Symbol>Cornice3Nasengesims.wrl</Symbol></Probability>
    <Probability value="0.2"><Symbol>Cornice4FallenderKarnies.wrl</Symbol></Probability>
    <Probability value="0.2"><Symbol>Cornice6Kranzleiste.wrl</Symbol></Probability>
  </Rules></Rule>
</Rulefile>)";

TEST(Derivation, T5BranchFrequenciesOverManyBuildings) {
    Fixture f(kCornices);
    uint32_t rule = *f.grammar->findRule("CorniceChoice");
    const int buildings = 100000;
    std::vector<int> counts(5, 0);
    for (int b = 0; b < buildings; ++b) ++counts[chooseBranch(*f.grammar, {0, uint32_t(b)}, rule)];
    double sigma = std::sqrt(buildings * 0.2 * 0.8);
    for (int c : counts) EXPECT_LT(std::abs(c - buildings * 0.2), 5 * sigma) << c;
}

TEST(Derivation, T5OneBuildingBranchesTheSameWayEverywhere) {
    Fixture f(kCornices);
    std::map<std::string, int> perBuilding;
    for (uint32_t building = 0; building < 50; ++building) {
        auto out = f.derive("Facade", {21, 15}, building);
        ASSERT_EQ(out.size(), 35u);
        for (const Terminal &t : out) EXPECT_EQ(t.model, out[0].model) << "building " << building;
        ++perBuilding[f.name(out[0])];
    }
    EXPECT_EQ(perBuilding.size(), 5u);  // different buildings do differ
    // The same building derives the same way again.
    auto again = f.derive("Facade", {21, 15}, 3);
    EXPECT_EQ(again[0].model, f.derive("Facade", {21, 15}, 3)[0].model);
}

TEST(Derivation, ConditionsChooseAmongTheBranchesThatFit) {
    Fixture f(R"(<Rulefile name="t"><Rule><Predecessor>Facade</Predecessor><Rules>
      <Probability value="0.5" min_width="6"><Symbol>Wide.wrl</Symbol></Probability>
      <Probability value="0.5" max_width="6"><Symbol>Narrow.wrl</Symbol></Probability>
      </Rules></Rule></Rulefile>)");
    for (uint32_t b = 0; b < 20; ++b) {
        EXPECT_EQ(f.name(f.derive("Facade", {10, 3}, b)[0]), "Wide.wrl");
        EXPECT_EQ(f.name(f.derive("Facade", {4, 3}, b)[0]), "Narrow.wrl");
    }
}

TEST(Derivation, T6SettingsPrecedenceLotBlockCityDefaults) {
    // Bilke 2009 listing 2.1: the city sets 12 ± 2 m, the second block's lot 16 m.
    SettingsMap city{{"BuildingHeight", number(12)}, {"BuildingHeightVar", number(2)}};
    SettingsMap block{{"LODLevel", number(1)}};
    SettingsMap lot{{"BuildingHeight", number(16)}};
    SettingsStack forLot({&lot, &block, &city, &defaultBuildingSettings()});
    SettingsStack forBlockLot({&block, &city, &defaultBuildingSettings()});
    SettingsStack bare({&defaultBuildingSettings()});
    EXPECT_EQ(forLot.number("BuildingHeight"), 16.0f);
    EXPECT_EQ(forBlockLot.number("BuildingHeight"), 12.0f);
    EXPECT_EQ(forBlockLot.number("LODLevel"), 1.0f);
    EXPECT_EQ(bare.number("BuildingHeight"), 15.0f);
    EXPECT_EQ(bare.number("FloorHeight"), 3.0f);
    EXPECT_EQ(bare.number("RoofHeight"), 4.0f);
    float lo = 1e9f, hi = -1e9f;
    for (uint32_t b = 0; b < 1000; ++b) {
        float h = randomiseHeights(forBlockLot, 0, b).building;
        lo = std::min(lo, h);
        hi = std::max(hi, h);
        float lotHeight = randomiseHeights(forLot, 0, b).building;
        EXPECT_GE(lotHeight, 14);
        EXPECT_LE(lotHeight, 18);
    }
    EXPECT_GE(lo, 10);
    EXPECT_LE(hi, 14);
    EXPECT_LT(lo, 10.2);  // the deviation is used in full
    EXPECT_GT(hi, 13.8);
    EXPECT_EQ(randomiseHeights(bare, 0, 5).building, 15.0f);
}

TEST(Derivation, PropertiesReadTheRandomisedHeights) {
    Fixture f(
        R"(<Rulefile name="t"><BuildingSettings><FloorHeight>3.5</FloorHeight><FloorHeightVar>0.5</FloorHeightVar></BuildingSettings>
      <Rule><Predecessor>Floors</Predecessor><Rules>
      <Probability value="1"><Repeat axis="u" size="1"/><Symbol property="FloorHeight">Floor.wrl</Symbol></Probability>
      </Rules></Rule></Rulefile>)");
    BuildingHeights heights = randomiseHeights(f.stack, 7, 1);
    EXPECT_GE(heights.floor, 3);
    EXPECT_LE(heights.floor, 4);
    auto out = f.derive("Floors", {10, 20}, 1, 7);
    EXPECT_EQ(int(out.size()), int(std::floor(20 / heights.floor + 1e-4f)));
}

TEST(Derivation, AMissingPropertyIsAnErrorAtTheSymbol) {
    Fixture f(kListing22);
    try {
        f.derive("Fassade2", {10, 15});
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("test.xml:46:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("FassadenelementBreite"), std::string::npos) << e.what();
    }
}

TEST(Derivation, ARuleThatKeepsChoosingItselfHitsTheDepthLimit) {
    // It can finish, so the rule file passes; but a building that takes the recursive branch
    // takes it everywhere, so it never does.
    Fixture f(R"(<Rulefile name="t"><Rule><Predecessor>Tower</Predecessor><Rules>
      <Probability value="0.5"><Split axis="u"/><Symbol size="3">Floor.wrl</Symbol><Symbol size="1r">Tower</Symbol></Probability>
      <Probability value="0.5"><Symbol>Roof.wrl</Symbol></Probability>
      </Rules></Rule></Rulefile>)");
    uint32_t rule = *f.grammar->findRule("Tower");
    uint32_t recursive = 0;
    while (chooseBranch(*f.grammar, {7, recursive}, rule) != 0) ++recursive;
    try {
        f.derive("Tower", {10, 1000}, recursive);
        FAIL() << "no error";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("test.xml:1:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("deeper than 64"), std::string::npos) << e.what();
    }
}

TEST(Derivation, AnUnknownStartSymbolIsAnError) {
    Fixture f(kListing22);
    EXPECT_THROW(f.derive("NoSuchFacade", {10, 15}), InputError);
}

}  // namespace
}  // namespace veduta
