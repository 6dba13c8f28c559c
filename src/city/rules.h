// The facade split grammar as a rule file describes it (Bilke 2009, §2.2.2–2.2.4):
// rules keyed by their predecessor symbol, each with probability branches that substitute,
// split or repeat. rule_file.h reads it from Bilke's XML; derivation.h applies it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "description/settings_map.h"
#include "facade/building_style.h"
#include "facade/profile.h"

namespace veduta {

// The two axes of a facade scope: r runs left to right, u bottom to top.
enum class SplitAxis { Right, Up };

// How a fitted model's depth follows its scope (Bilke 2009, §2.4, Shape::GetTransformMatrix).
// NotSet lets the model type decide.
enum class ZScale { NotSet, None, Right, Up, Average };

// A size along a split or repeat axis: metres ("4"), a share of what the absolute sizes leave
// ("1r"), or, for repeats, a floating target ("~2.1", an extension after CGA's `~`).
struct Extent {
    enum class Unit { Absolute, Relative, Floating };
    float value = 1;
    Unit unit = Unit::Relative;
};

// One successor in a branch: a rule's predecessor or a terminal model, with the attributes
// of Bilke's <Symbol>.
struct Successor {
    std::string name;  // trimmed; terminals keep their ".wrl"
    FileLoc loc;
    Extent size;                         // along the split axis; unused in substitutions and repeats
    std::string property;                // a setting that multiplies an absolute size (or a repeat's)
    std::optional<std::string> texture;  // '/' separated, relative to the textures folder
    Vec3f scale{1.0f};                   // (right, up, out)
    Vec3f translate{0.0f};               // metres, (right, up, out); +out points away from the wall
    std::optional<Vec2f> uv;             // texture tiles are uv × their size: "0.5 0.5" tiles twice as often
    ZScale zScale = ZScale::NotSet;
};

// A condition on the scope a branch would derive (an extension): the branch is eligible only
// when the scope's width and height lie within these bounds, in metres.
struct ScopeCondition {
    float minWidth = 0, maxWidth = 1e30f;
    float minHeight = 0, maxHeight = 1e30f;
    bool holdsFor(float width, float height) const {
        return width >= minWidth && width <= maxWidth && height >= minHeight && height <= maxHeight;
    }
};

// One <Probability> branch of a rule.
struct Branch {
    enum class Kind { Substitution, Split, Repeat };
    Kind kind = Kind::Substitution;
    float probability = 1;  // renormalised over the rule's branches when the file's do not sum to 1
    SplitAxis axis = SplitAxis::Right;
    Extent repeatSize;  // Repeat: the tile size before the first successor's property multiplies it
    ScopeCondition condition;
    std::vector<Successor> successors;
    FileLoc loc;
};

struct Rule {
    std::string predecessor;
    std::vector<Branch> branches;
    FileLoc loc;
};

// All rules of a rule file and the files it includes.
// <Masonry model="Wall0.wrl" facades="SideFacade SmallFacade" bricks="party.bricks" unit="0.01"/>
// (or ashlar=, cyclopean=): the walls the rules build from that wall model on those facades (start
// symbols; all when not given) get Finkenzeller's masonry (docs/facades.md), baked at the camera's
// texels, instead of the model's own texture.
struct MasonryRule {
    std::string model;
    std::vector<std::string> facades;  // empty: every facade
    MasonryStyle style;
    FileLoc loc;

    bool covers(const std::string &facade) const {
        return facades.empty() || std::find(facades.begin(), facades.end(), facade) != facades.end();
    }
};

// <Cornice model="Cornice6Kranzleiste.wrl" rules="TopFloor SideFacade" profile="main.cornice"/>:
// where those rules (all when not given) place that model, it is not set as an instance; the
// places at one height are joined along the facade and round the building's corners and swept
// with the profile's description (a cornice file, docs/facades.md), mitred, with its consoles.
struct CorniceRule {
    std::string model;
    std::vector<std::string> rules;  // empty: wherever the model is placed
    std::shared_ptr<const CorniceDescription> cornice;
    std::filesystem::path directory;  // the cornice file's, where its consoles' files are found
    FileLoc loc;
};

struct RuleSet {
    std::string name;  // Rulefile@name of the file that was read
    // In file order (an including file's own first): for a wall, the first that covers it.
    std::vector<MasonryRule> masonry;
    // In file order, as masonry; for a model placed by a rule, the first that takes it.
    std::vector<CorniceRule> cornices;
    std::vector<Rule> rules;
    std::unordered_map<std::string, uint32_t> ruleIndex;  // predecessor → index into rules
    // The rule files' <BuildingSettings>, defaults for properties the rules use; the first
    // definition in file order wins (an including file's own come first).
    std::unordered_map<std::string, SettingValue> settings;
    std::vector<std::string> warnings;  // "file:line:col: message", for the caller to print

    const Rule *find(const std::string &predecessor) const {
        auto it = ruleIndex.find(predecessor);
        return it == ruleIndex.end() ? nullptr : &rules[it->second];
    }
};

}  // namespace veduta
