#include <unistd.h>

#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "city/listing_2_2.h"
#include "city/rule_file.h"
#include "core/error.h"
#include "input_error.h"

namespace veduta {
namespace {

bool isWrl(std::string_view name) { return name.ends_with(".wrl"); }

// The listing's leaves have no rules of their own: an asset library that knows them.
bool listingModels(std::string_view name) {
    return isWrl(name) || name == "WeitereEtagen" || name == "Fassadenelement";
}

// A rule file of one rule, 'A', whose <Rules> hold `branches` from line 3, column 1.
std::string ruleA(const std::string &branches) {
    return fmt::format(
        "<Rulefile name=\"t\">\n<Rule><Predecessor>A</Predecessor><Rules>\n{}\n</Rules></Rule>\n"
        "</Rulefile>",
        branches);
}

RuleSet parse(const std::string &xml) { return parseRuleFile(xml, "t.xml", isWrl); }

// The message of the InputError that reading `xml` throws.
std::string errorOf(const std::string &xml) {
    return test::inputErrorOf([&] { parse(xml); });
}

TEST(RuleFile, ListingTwoTwoParses) {
    RuleSet set = parseRuleFile(kListing22, "listing.xml", listingModels);
    EXPECT_EQ(set.name, "SimpleBuildingVar");
    EXPECT_TRUE(set.warnings.empty());
    ASSERT_EQ(set.rules.size(), 3u);

    const Rule *start = set.find("FassadeStart");
    ASSERT_NE(start, nullptr);
    EXPECT_EQ(start->loc.line, 6);
    ASSERT_EQ(start->branches.size(), 2u);
    for (const Branch &b : start->branches) {
        EXPECT_EQ(b.kind, Branch::Kind::Substitution);
        EXPECT_FLOAT_EQ(b.probability, 0.5f);
        ASSERT_EQ(b.successors.size(), 1u);
    }
    EXPECT_EQ(start->branches[0].successors[0].name, "Fassade1");
    EXPECT_EQ(start->branches[1].successors[0].name, "Fassade2");

    const Rule *split = set.find("Fassade1");
    ASSERT_NE(split, nullptr);
    ASSERT_EQ(split->branches.size(), 1u);
    const Branch &s = split->branches[0];
    EXPECT_EQ(s.kind, Branch::Kind::Split);
    EXPECT_EQ(s.axis, SplitAxis::Up);
    ASSERT_EQ(s.successors.size(), 2u);
    EXPECT_EQ(s.successors[0].name, "Bodenetage.wrl");
    EXPECT_EQ(s.successors[0].size.unit, Extent::Unit::Absolute);
    EXPECT_EQ(s.successors[0].size.value, 4.0f);
    EXPECT_EQ(s.successors[0].texture, "Bodenetage.jpg");
    EXPECT_EQ(s.successors[0].loc.line, 30);
    EXPECT_EQ(s.successors[0].loc.column, 9);
    EXPECT_EQ(s.successors[1].name, "WeitereEtagen");
    EXPECT_EQ(s.successors[1].size.unit, Extent::Unit::Relative);
    EXPECT_EQ(s.successors[1].size.value, 1.0f);
    EXPECT_FALSE(s.successors[1].texture.has_value());

    const Rule *repeat = set.find("Fassade2");
    ASSERT_NE(repeat, nullptr);
    const Branch &r = repeat->branches[0];
    EXPECT_EQ(r.kind, Branch::Kind::Repeat);
    EXPECT_EQ(r.axis, SplitAxis::Right);
    EXPECT_EQ(r.repeatSize.unit, Extent::Unit::Absolute);
    EXPECT_EQ(r.repeatSize.value, 1.0f);
    ASSERT_EQ(r.successors.size(), 1u);
    EXPECT_EQ(r.successors[0].name, "Fassadenelement");
    EXPECT_EQ(r.successors[0].property, "FassadenelementBreite");
}

TEST(RuleFile, ListingTwoTwoNamesItsUndefinedLeaves) {
    EXPECT_EQ(errorOf(kListing22),
              "t.xml:33:9: unknown symbol 'WeitereEtagen': no rule derives it and it is not a model");
}

TEST(RuleFile, ListingTwoTwoAsTruncatedIsAnXmlError) {
    std::string truncated = kListing22;
    truncated.erase(truncated.rfind('>'));
    EXPECT_EQ(errorOf(truncated), "t.xml:53:10: Error parsing end element tag");
}

// Bilke 2009, ch. 4, L2424–2439, verbatim: a split and a substitution whose uv is broken over two lines.
TEST(RuleFile, OutpickingOrnamentWallParsesVerbatim) {
    RuleSet set = parse(R"(<Rulefile name="ornaments">
<Rule>
  <Predecessor>OutpickingOrnamentWall</Predecessor>
  <Rules>
    <Probability value="0.500000">
      <Split axis="r" />
      <Symbol size="1r" z_scale="none">Wall+1.wrl</Symbol>
      <Symbol size="6r" texture="miscNormal\OrnamentBorder0081_S.jpg"
        z_scale="none">Glass+1.wrl</Symbol>
      <Symbol size="1r" z_scale="none">Wall+1.wrl</Symbol>
    </Probability>
    <Probability value="0.500000">
      <Symbol texture="miscNormal\OrnamentBorder0093_2_S.jpg" uv="0.25
        1" z_scale="none">Glass+1.wrl</Symbol>
    </Probability>
  </Rules>
</Rule>
</Rulefile>)");
    EXPECT_TRUE(set.warnings.empty());
    const Rule *rule = set.find("OutpickingOrnamentWall");
    ASSERT_NE(rule, nullptr);
    ASSERT_EQ(rule->branches.size(), 2u);
    const Branch &split = rule->branches[0];
    EXPECT_EQ(split.kind, Branch::Kind::Split);
    EXPECT_EQ(split.axis, SplitAxis::Right);
    ASSERT_EQ(split.successors.size(), 3u);
    EXPECT_EQ(split.successors[1].size.value, 6.0f);
    EXPECT_EQ(split.successors[1].size.unit, Extent::Unit::Relative);
    EXPECT_EQ(split.successors[1].texture, "miscNormal/OrnamentBorder0081_S.jpg");
    for (const Successor &s : split.successors) EXPECT_EQ(s.zScale, ZScale::None);
    const Branch &flat = rule->branches[1];
    EXPECT_EQ(flat.kind, Branch::Kind::Substitution);
    EXPECT_FLOAT_EQ(flat.probability, 0.5f);
    ASSERT_EQ(flat.successors.size(), 1u);
    const Successor &glass = flat.successors[0];
    EXPECT_EQ(glass.name, "Glass+1.wrl");
    EXPECT_EQ(glass.texture, "miscNormal/OrnamentBorder0093_2_S.jpg");
    ASSERT_TRUE(glass.uv.has_value());
    EXPECT_EQ(glass.uv->x, 0.25f);
    EXPECT_EQ(glass.uv->y, 1.0f);
}

TEST(RuleFile, ReadsEverySymbolAttribute) {
    RuleSet set = parse(ruleA(R"(<Probability value="1"><Split axis="r"/>
<Symbol size="2" property="TileWidth" texture="reflection\metal\Alu.png" scale="0.05 0.9
  0.05" translate="-0.25	0.05 -0.1" uv="0.5 2" z_scale="average">c.wrl</Symbol>
<Symbol>d.wrl</Symbol></Probability>)"));
    const Branch &b = set.rules[0].branches[0];
    const Successor &c = b.successors[0];
    EXPECT_EQ(c.size.value, 2.0f);
    EXPECT_EQ(c.size.unit, Extent::Unit::Absolute);
    EXPECT_EQ(c.property, "TileWidth");
    EXPECT_EQ(c.texture, "reflection/metal/Alu.png");
    EXPECT_EQ(c.scale, Vec3f(0.05f, 0.9f, 0.05f));
    EXPECT_EQ(c.translate, Vec3f(-0.25f, 0.05f, -0.1f));
    EXPECT_EQ(c.uv->x, 0.5f);
    EXPECT_EQ(c.uv->y, 2.0f);
    EXPECT_EQ(c.zScale, ZScale::Average);
    // A split symbol without size takes one share; the others keep their defaults.
    const Successor &d = b.successors[1];
    EXPECT_EQ(d.size.unit, Extent::Unit::Relative);
    EXPECT_EQ(d.size.value, 1.0f);
    EXPECT_EQ(d.scale, Vec3f(1.0f));
    EXPECT_EQ(d.translate, Vec3f(0.0f));
    EXPECT_FALSE(d.uv.has_value());
    EXPECT_EQ(d.zScale, ZScale::NotSet);
}

TEST(RuleFile, BuildingSettingsKeepTheFirstDefinition) {
    RuleSet set = parse(R"(<Rulefile name="t">
<BuildingSettings><FloorHeight> 3.5 </FloorHeight><Style>Gruenderzeit</Style></BuildingSettings>
<BuildingSettings><FloorHeight>4</FloorHeight></BuildingSettings>
<Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>a.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    ASSERT_EQ(set.settings.size(), 2u);
    const SettingValue &floor = set.settings.at("FloorHeight");
    EXPECT_EQ(floor.number, 3.5f);
    EXPECT_EQ(floor.loc.line, 2);
    EXPECT_EQ(floor.loc.column, 33);  // the value, which a message about it points at
    const SettingValue &style = set.settings.at("Style");
    EXPECT_EQ(style.text, "Gruenderzeit");
    EXPECT_FALSE(style.number.has_value());
}

TEST(RuleFile, MalformedNumbersAndVectors) {
    const char *symbol = R"(<Probability value="1"><Split axis="r"/><Symbol )";
    auto error = [&](const std::string &attributes) {
        return errorOf(ruleA(fmt::format("{}{}>a.wrl</Symbol></Probability>", symbol, attributes)));
    };
    // The symbol's attributes start at column 49, so a value starts at 49 + its name's length + 2.
    EXPECT_EQ(error(R"(size="4x")"),
              "t.xml:3:55: '4x' is not a size: give metres ('4'), a share ('1r') or a "
              "floating repeat size ('~2.1')");
    EXPECT_EQ(error(R"(size="r")"),
              "t.xml:3:55: 'r' is not a size: give metres ('4'), a share ('1r') or a "
              "floating repeat size ('~2.1')");
    EXPECT_EQ(error(R"(scale="1 1")"), "t.xml:3:56: attribute 'scale' takes three numbers");
    EXPECT_EQ(error(R"(translate="0 0 x")"), "t.xml:3:60: 'x' is not a number (attribute 'translate')");
    EXPECT_EQ(error(R"(uv="1 1 1")"), "t.xml:3:53: attribute 'uv' takes two numbers");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="0.5x"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:21: '0.5x' is not a number (attribute 'value')");
}

TEST(RuleFile, SizesMustBePositive) {
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1"><Split axis="u"/><Symbol size="-1">a.wrl</Symbol></Probability>)")),
        "t.xml:3:55: size '-1' is not positive");
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1"><Split axis="u"/><Symbol size="0r">a.wrl</Symbol></Probability>)")),
        "t.xml:3:55: size '0r' is not positive");
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1"><Repeat axis="u" size="0"/><Symbol>a.wrl</Symbol></Probability>)")),
        "t.xml:3:47: size '0' is not positive");
}

TEST(RuleFile, ProbabilitiesMustBeFiniteAndNotNegative) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="-0.5"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:21: probability -0.5 is negative");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="inf"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:21: 'inf' is not a number (attribute 'value')");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="nan"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:21: 'nan' is not a number (attribute 'value')");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:1: <Probability> needs the attribute 'value'");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="0"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:2:1: the probabilities of rule 'A' are all 0");
}

TEST(RuleFile, RepeatNeedsAnAbsoluteSize) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Repeat axis="r"/><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:24: <Repeat> needs the attribute 'size'");
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1"><Repeat axis="r" size="1r"/><Symbol>a.wrl</Symbol></Probability>)")),
        "t.xml:3:47: a repeat's size is absolute ('2') or floating ('~2'), not relative");
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1"><Split axis="r"/><Symbol size="~2">a.wrl</Symbol></Probability>)")),
        "t.xml:3:55: a floating size ('~') is for <Repeat>, not <Symbol>");
}

TEST(RuleFile, UnknownAxisAndZScale) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Split axis="x"/><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:37: unknown axis 'x': expected r (right) or u (up)");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol z_scale="left">a.wrl</Symbol></Probability>)")),
              "t.xml:3:41: unknown z_scale 'left': expected none, right, up or average");
}

TEST(RuleFile, MisplacedAndUnknownElementsAndAttributes) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol>a.wrl</Symbol><Split axis="r"/></Probability>)")),
              "t.xml:3:46: <Split> can only be the first element of <Probability>");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol colour="red">a.wrl</Symbol></Probability>)")),
              "t.xml:3:32: unknown attribute 'colour' on <Symbol>");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Shape>a.wrl</Shape></Probability>)")),
              "t.xml:3:24: unknown element <Shape> in <Probability>");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol>a.wrl b.wrl</Symbol></Probability>)")),
              "t.xml:3:24: 'a.wrl b.wrl' is not a symbol name: it contains white space");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol>  </Symbol></Probability>)")),
              "t.xml:3:24: <Symbol> holds no symbol name");
    EXPECT_EQ(errorOf("<Rules name=\"t\"/>"), "t.xml:1:1: the root element is <Rules>, expected <Rulefile>");
}

TEST(RuleFile, EveryRuleNeedsABranchAndEveryBranchASymbol) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Split axis="r"/></Probability>)")),
              "t.xml:3:1: the branch has no <Symbol>");
    EXPECT_EQ(errorOf(ruleA("")), "t.xml:2:1: rule 'A' has no <Probability> branch");
    EXPECT_EQ(errorOf("<Rulefile name=\"t\">\n  <Rule><Rules/></Rule>\n</Rulefile>"),
              "t.xml:2:3: <Rule> needs a <Predecessor>");
}

TEST(RuleFile, PredecessorDefinedTwice) {
    EXPECT_EQ(errorOf(R"(<Rulefile name="t">
<Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>a.wrl</Symbol></Probability></Rules></Rule>
  <Rule><Predecessor>
    A
  </Predecessor><Rules><Probability value="1"><Symbol>b.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)"),
              "t.xml:3:3: rule 'A' is defined twice: first at t.xml:2:1");
}

TEST(RuleFile, UnknownSymbol) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1"><Symbol>a.wrl</Symbol>
  <Symbol>Foo</Symbol></Probability>)")),
              "t.xml:4:3: unknown symbol 'Foo': no rule derives it and it is not a model");
}

TEST(RuleFile, RuleThatDerivesItselfForever) {
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="0.5"><Symbol>A</Symbol></Probability>
<Probability value="0.5"><Split axis="r"/><Symbol>a.wrl</Symbol><Symbol>A</Symbol></Probability>)")),
              "t.xml:2:1: rule 'A' can never finish: every branch derives A again");
}

TEST(RuleFile, RecursionWithAWayOutIsFine) {
    RuleSet set =
        parse(ruleA(R"(<Probability value="0.5"><Split axis="u"/><Symbol>a.wrl</Symbol><Symbol>A</Symbol></Probability>
<Probability value="0.5"><Symbol>a.wrl</Symbol></Probability>)"));
    EXPECT_EQ(set.rules.size(), 1u);
}

// C cannot finish because it derives A, but the cycle A → B → A is the cause: it is named.
TEST(RuleFile, CycleOfRulesIsNamedAtItsFirstRule) {
    EXPECT_EQ(errorOf(R"(<Rulefile name="t">
<Rule><Predecessor>C</Predecessor><Rules><Probability value="1"><Symbol>A</Symbol></Probability></Rules></Rule>
<Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>B</Symbol></Probability></Rules></Rule>
<Rule><Predecessor>B</Predecessor><Rules>
  <Probability value="0.5"><Symbol>a.wrl</Symbol><Symbol>A</Symbol></Probability>
  <Probability value="0.5"><Symbol>B</Symbol></Probability>
</Rules></Rule>
</Rulefile>)"),
              "t.xml:3:1: rule 'A' can never finish: every branch derives a rule that cannot finish, round the cycle "
              "A → B → A");
}

// Rule files that generators write: a chain of 30,000 rules, each deriving the next, read in
// time linear in the rules (the fixed point used to take one pass per rule), and the same
// chain ending in a cycle, which is named at its first rule.
std::string chain(int rules, const std::string &last) {
    std::string xml = "<Rulefile name=\"t\">\n";
    for (int i = 0; i < rules; ++i) {
        std::string next = i + 1 < rules ? fmt::format("R{}", i + 1) : last;
        xml += fmt::format(
            "<Rule><Predecessor>R{}</Predecessor><Rules><Probability value=\"1\"><Symbol>{}</Symbol>"
            "</Probability></Rules></Rule>\n",
            i, next);
    }
    return xml;
}

TEST(RuleFile, LongChainsOfRulesAreRead) {
    RuleSet set = parse(chain(30000, "a.wrl") + "</Rulefile>");
    EXPECT_EQ(set.rules.size(), 30000u);
    EXPECT_EQ(errorOf(chain(30000, "X") +
                      "<Rule><Predecessor>X</Predecessor><Rules><Probability value=\"1\"><Symbol>Y</Symbol>"
                      "</Probability></Rules></Rule>\n"
                      "<Rule><Predecessor>Y</Predecessor><Rules><Probability value=\"1\"><Symbol>X</Symbol>"
                      "</Probability></Rules></Rule>\n</Rulefile>"),
              "t.xml:30002:1: rule 'X' can never finish: every branch derives a rule that cannot finish, round the "
              "cycle X → Y → X");
}

// Bilke's GroundfloorWindowTileChoice (L2040–2050): its only branch has probability 0.5.
TEST(RuleFile, ProbabilitiesNotSummingToOneAreWarnedAndRenormalised) {
    RuleSet set = parse(R"(<Rulefile name="t">
<Rule>
  <Predecessor>GroundfloorWindowTileChoice</Predecessor>
  <Rules>
    <Probability value="0.500000">
      <Split axis="r" />
      <Symbol size="1r">Wall0.wrl</Symbol>
      <Symbol size="1" property="GroundfloorWindowWidth">
        WindowPlaceXChoice</Symbol>
      <Symbol size="1r">Wall0.wrl</Symbol>
    </Probability>
  </Rules>
</Rule>
<Rule><Predecessor>WindowPlaceXChoice</Predecessor><Rules>
  <Probability value="0.333333"><Symbol>SmallRoof1.wrl</Symbol></Probability>
  <Probability value="0.333333"><Symbol>SmallRoofArc.wrl</Symbol></Probability>
  <Probability value="0.333333"><Symbol>SmallRoofTri.wrl</Symbol></Probability>
</Rules></Rule>
</Rulefile>)");
    ASSERT_EQ(set.warnings.size(), 1u);
    EXPECT_EQ(set.warnings[0],
              "t.xml:2:1: the probabilities of rule 'GroundfloorWindowTileChoice' sum to 0.5, not 1; "
              "they are scaled to sum to 1");
    EXPECT_FLOAT_EQ(set.find("GroundfloorWindowTileChoice")->branches[0].probability, 1.0f);
    // Thirds written to six places are within the tolerance, and are scaled all the same.
    float sum = 0;
    for (const Branch &b : set.find("WindowPlaceXChoice")->branches) sum += b.probability;
    EXPECT_FLOAT_EQ(sum, 1.0f);
}

TEST(RuleFile, SizeOutsideASplitIsWarnedAbout) {
    RuleSet set = parse(ruleA(R"(<Probability value="1"><Symbol size="2">a.wrl</Symbol></Probability>)"));
    ASSERT_EQ(set.warnings.size(), 1u);
    EXPECT_EQ(set.warnings[0], "t.xml:3:38: 'size' has no effect outside a split; it is ignored");
}

TEST(RuleFile, FloatingRepeatAndScopeConditions) {
    RuleSet set = parse(ruleA(R"(<Probability value="0.5" min_width="2" max_width="8.5" min_height="1" max_height="3">
  <Repeat axis="u" size="~2.1"/><Symbol>a.wrl</Symbol></Probability>
<Probability value="0.5"><Symbol>b.wrl</Symbol></Probability>)"));
    const Branch &b = set.rules[0].branches[0];
    EXPECT_EQ(b.kind, Branch::Kind::Repeat);
    EXPECT_EQ(b.axis, SplitAxis::Up);
    EXPECT_EQ(b.repeatSize.unit, Extent::Unit::Floating);
    EXPECT_EQ(b.repeatSize.value, 2.1f);
    EXPECT_EQ(b.condition.minWidth, 2.0f);
    EXPECT_EQ(b.condition.maxWidth, 8.5f);
    EXPECT_EQ(b.condition.minHeight, 1.0f);
    EXPECT_EQ(b.condition.maxHeight, 3.0f);
    // Without bounds a branch holds for every scope.
    EXPECT_TRUE(set.rules[0].branches[1].condition.holdsFor(0, 1e6f));
}

TEST(RuleFile, ScopeConditionBoundsMustBeOrdered) {
    EXPECT_EQ(
        errorOf(ruleA(R"(<Probability value="1" min_width="3" max_width="2"><Symbol>a.wrl</Symbol></Probability>)")),
        "t.xml:3:49: max_width 2 is less than min_width 3");
    EXPECT_EQ(errorOf(ruleA(R"(<Probability value="1" min_height="-1"><Symbol>a.wrl</Symbol></Probability>)")),
              "t.xml:3:36: attribute 'min_height' is -1, which is negative");
}

// Rule files written to a fresh folder.
class RuleFileIncludes : public testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::path(testing::TempDir()) / fmt::format("veduta_rule_file_{}", getpid());
        std::filesystem::create_directories(dir_ / "parts");
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::filesystem::path write(const std::string &name, const std::string &text) const {
        std::filesystem::path file = dir_ / name;
        std::ofstream(file) << text;
        return file;
    }

    std::string errorOfFile(const std::filesystem::path &file, const RuleFileLimits &limits = {}) const {
        return test::inputErrorOf([&] { readRuleFile(file, isWrl, limits); });
    }

    std::filesystem::path dir_;
};

TEST_F(RuleFileIncludes, IncludedRulesAndSettingsAreAdded) {
    std::filesystem::path main = write("main.xml", R"(<Rulefile name="main">
  <Include file="parts/floors.xml"/>
  <BuildingSettings><FloorHeight>3</FloorHeight></BuildingSettings>
  <Rule><Predecessor>Facade</Predecessor><Rules>
    <Probability value="1"><Repeat axis="u" size="1"/><Symbol property="FloorHeight">Floor</Symbol></Probability>
  </Rules></Rule>
</Rulefile>)");
    // Relative to the including file: parts/floors.xml includes parts/../tiles.xml.
    write("parts/floors.xml", R"(<Rulefile name="floors">
  <BuildingSettings><FloorHeight>4</FloorHeight><TileWidth>1.5</TileWidth></BuildingSettings>
  <Include file="../tiles.xml"/>
  <Rule><Predecessor>Floor</Predecessor><Rules>
    <Probability value="1"><Repeat axis="r" size="1"/><Symbol property="TileWidth">Tile</Symbol></Probability>
  </Rules></Rule>
</Rulefile>)");
    write("tiles.xml", R"(<Rulefile name="tiles">
  <Rule><Predecessor>Tile</Predecessor><Rules><Probability value="1"><Symbol>Window1.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    RuleSet set = readRuleFile(main, isWrl);
    EXPECT_EQ(set.name, "main");
    ASSERT_EQ(set.rules.size(), 3u);
    EXPECT_EQ(set.rules[0].predecessor, "Facade");
    EXPECT_EQ(set.rules[1].predecessor, "Floor");
    EXPECT_EQ(set.rules[2].predecessor, "Tile");
    EXPECT_EQ(set.rules[2].loc.file, (dir_ / "parts/../tiles.xml").string());
    for (uint32_t i = 0; i < set.rules.size(); ++i) EXPECT_EQ(set.ruleIndex.at(set.rules[i].predecessor), i);
    // The including file's own setting wins over the included file's, though written after the include.
    EXPECT_EQ(set.settings.at("FloorHeight").number, 3.0f);
    EXPECT_EQ(set.settings.at("TileWidth").number, 1.5f);
}

TEST_F(RuleFileIncludes, PredecessorDefinedInTwoFiles) {
    std::filesystem::path main = write("main.xml", R"(<Rulefile name="main">
  <Include file="other.xml"/>
  <Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>a.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    std::filesystem::path other = write("other.xml", R"(<Rulefile name="other">
 <Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>b.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    EXPECT_EQ(errorOfFile(main),
              fmt::format("{}:2:2: rule 'A' is defined twice: first at {}:3:3", other.string(), main.string()));
}

TEST_F(RuleFileIncludes, IncludeCycle) {
    std::filesystem::path a = write("a.xml", R"(<Rulefile name="a">
  <Include file="parts/b.xml"/>
  <Rule><Predecessor>A</Predecessor><Rules><Probability value="1"><Symbol>a.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    write("parts/b.xml", "<Rulefile name=\"b\">\n  <Include file=\"../a.xml\"/>\n</Rulefile>");
    std::filesystem::path b = dir_ / "parts/b.xml", again = dir_ / "parts/../a.xml";
    EXPECT_EQ(errorOfFile(a),
              fmt::format("{}:2:18: the includes form a cycle: {} → {} → {}", b.string(), a.string(), b.string(),
                          again.string()));
}

TEST_F(RuleFileIncludes, IncludesNestedTooDeep) {
    std::filesystem::path a = write("a.xml", "<Rulefile name=\"a\">\n<Include file=\"b.xml\"/>\n</Rulefile>");
    write("b.xml", "<Rulefile name=\"b\">\n<Include file=\"c.xml\"/>\n</Rulefile>");
    write("c.xml", R"(<Rulefile name="c">
  <Rule><Predecessor>C</Predecessor><Rules><Probability value="1"><Symbol>c.wrl</Symbol></Probability></Rules></Rule>
</Rulefile>)");
    EXPECT_EQ(readRuleFile(a, isWrl, {2}).rules.size(), 1u);
    EXPECT_EQ(errorOfFile(a, {1}),
              fmt::format("{}:2:1: includes are nested more than 1 deep", (dir_ / "b.xml").string()));
}

TEST_F(RuleFileIncludes, MissingFilesAreNamed) {
    std::filesystem::path missing = dir_ / "missing.xml";
    EXPECT_EQ(errorOfFile(missing), fmt::format("{}: cannot open file", missing.string()));
    std::filesystem::path main =
        write("main.xml", "<Rulefile name=\"main\">\n  <Include file=\"missing.xml\"/>\n</Rulefile>");
    EXPECT_EQ(errorOfFile(main), fmt::format("{}:2:18: {}: cannot open file", main.string(), missing.string()));
}

}  // namespace
}  // namespace veduta
