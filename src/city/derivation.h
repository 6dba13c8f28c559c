// Deriving a facade from a start shape with a split grammar (Bilke 2009, §2.2.2–2.2.4):
// substitution, split and repeat, inherited attributes, transforms that carry their scale to
// the descendants, and one branch per rule and building.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "city/building_settings.h"
#include "city/rules.h"
#include "core/vecmath.h"

namespace veduta {

// A rule set with every successor resolved to the rule or model it names and the branch
// probabilities normalised, ready to derive many buildings from (shared between threads).
class Grammar {
  public:
    // `modelIndex` maps a terminal's name to its model; the rule set has been checked
    // (readRuleFile), so every successor names a rule or a model. The grammar keeps a pointer
    // to `rules`, which must outlive it.
    using ModelIndex = std::function<std::optional<uint32_t>(std::string_view)>;
    Grammar(const RuleSet &rules, const ModelIndex &modelIndex);
    Grammar(RuleSet &&, const ModelIndex &) = delete;

    struct Target {
        bool isModel = false;
        uint32_t index = 0;  // into rules() or the model library
    };
    const RuleSet &rules() const { return *rules_; }
    const Target &target(uint32_t rule, uint32_t branch, uint32_t successor) const;
    // The branch probabilities of a rule, summing to 1.
    const std::vector<float> &probabilities(uint32_t rule) const { return probabilities_[rule]; }
    // A hash of the rule's name: what its random choices are keyed by.
    uint32_t ruleKey(uint32_t rule) const { return ruleKeys_[rule]; }
    std::optional<uint32_t> findRule(const std::string &predecessor) const;

  private:
    const RuleSet *rules_;
    std::vector<std::vector<std::vector<Target>>> targets_;  // [rule][branch][successor]
    std::vector<std::vector<float>> probabilities_;
    std::vector<uint32_t> ruleKeys_;
};

// A terminal shape: a model to fit into a scope.
struct Terminal {
    uint32_t model = 0;
    // The shape's frame → the start shape's facade frame (right, up, out; origin at the facade's
    // lower left). The shape's frame has its origin at the scope's centre, in the wall plane, and
    // carries every scale and translation of the shape's ancestors.
    Transform shapeToFacade;
    Vec2f size;                            // the scope's width and height, metres (not scaled)
    const std::string *texture = nullptr;  // the inherited texture attribute, if any
    Vec2f uv{1.0f, 1.0f};
    ZScale zScale = ZScale::NotSet;
    uint32_t rule = ~0u;  // the rule that placed it (index into the grammar's rules); ~0u: none
};

struct DerivationLimits {
    int maxDepth = 64;
    size_t maxShapes = 200000;  // rules applied and terminals made, per start shape
};

// Where the random choices come from: a branch is a pure function of the seed, the building
// and the rule, so a rule branches the same way everywhere in one building (L1966).
struct DerivationSeed {
    uint32_t seed = 0;
    uint32_t buildingId = 0;
};

// Derives `startSymbol` on a width × height facade and appends its terminals. Warnings (absolute
// sizes that overflow a split) are appended once per rule branch as "file:line:col: message".
// Throws InputError for a missing property, an unknown start symbol, or a derivation that
// exceeds the limits.
void deriveFacade(const Grammar &grammar, const std::string &startSymbol, Vec2f size,
                  const BuildingProperties &properties, const DerivationSeed &seed, std::vector<Terminal> &out,
                  std::vector<std::string> &warnings, const DerivationLimits &limits = {});

// The branch a rule takes for a building when all its branches are eligible: exposed for tests
// of the branch frequencies.
uint32_t chooseBranch(const Grammar &grammar, const DerivationSeed &seed, uint32_t rule);

}  // namespace veduta
