#include "city/derivation.h"

#include <cmath>
#include <stdexcept>
#include <unordered_set>

#include <fmt/format.h>

#include "core/check.h"
#include "core/hash.h"
#include "core/random_streams.h"

namespace veduta {

Grammar::Grammar(const RuleSet &rules, const ModelIndex &modelIndex) : rules_(&rules) {
    targets_.resize(rules.rules.size());
    probabilities_.resize(rules.rules.size());
    ruleKeys_.resize(rules.rules.size());
    for (uint32_t r = 0; r < rules.rules.size(); ++r) {
        const Rule &rule = rules.rules[r];
        ruleKeys_[r] = hashString(rule.predecessor);
        for (const Branch &branch : rule.branches) {
            probabilities_[r].push_back(branch.probability);  // the reader has made them sum to 1
            auto &targets = targets_[r].emplace_back();
            for (const Successor &successor : branch.successors) {
                if (auto ruleIndex = findRule(successor.name)) targets.push_back({false, *ruleIndex});
                else if (auto model = modelIndex(successor.name)) targets.push_back({true, *model});
                else  // readRuleFile reports these at their place
                    VEDUTA_UNREACHABLE(fmt::format("the rule set was not checked: '{}' is unknown", successor.name));
            }
        }
    }
}

const Grammar::Target &Grammar::target(uint32_t rule, uint32_t branch, uint32_t successor) const {
    return targets_[rule][branch][successor];
}

std::optional<uint32_t> Grammar::findRule(const std::string &predecessor) const {
    auto it = rules_->ruleIndex.find(predecessor);
    return it == rules_->ruleIndex.end() ? std::nullopt : std::optional(it->second);
}

namespace {

// Keyed by the rule's name, not its place in the file: adding or moving a rule leaves the
// other rules' choices as they were.
float branchVariate(const DerivationSeed &seed, uint32_t ruleKey) {
    return bitsToUnitFloat(hashValues({seed.seed, seed.buildingId, streamTag(RandomStream::RuleBranches), ruleKey}));
}

// Picks by the cumulative probabilities of the eligible branches; kNone when none is eligible.
constexpr uint32_t kNone = ~0u;

template <typename Eligible>
uint32_t pickBranch(const std::vector<float> &probabilities, float u, Eligible eligible) {
    float total = 0;
    uint32_t last = kNone;
    for (uint32_t b = 0; b < probabilities.size(); ++b)
        if (eligible(b)) {
            total += probabilities[b];
            last = b;
        }
    if (last == kNone) return kNone;
    float target = u * total, cumulative = 0;
    for (uint32_t b = 0; b < probabilities.size(); ++b) {
        if (!eligible(b)) continue;
        cumulative += probabilities[b];
        if (target < cumulative) return b;
    }
    return last;  // u * total rounded up to the sum
}

// The state a shape passes on to its successors.
struct Shape {
    Transform toFacade;  // origin at the scope's centre
    Vec2f size;
    const std::string *texture = nullptr;
    Vec2f uv{1.0f, 1.0f};
    ZScale zScale = ZScale::NotSet;
};

class Derivation {
  public:
    Derivation(const Grammar &grammar, const BuildingProperties &properties, const DerivationSeed &seed,
               std::vector<Terminal> &out, std::vector<std::string> &warnings, const DerivationLimits &limits) :
        grammar_(grammar), properties_(properties), seed_(seed), out_(out), warnings_(warnings), limits_(limits) {}

    void deriveRule(uint32_t rule, const Shape &shape, int depth);

  private:
    void deriveSuccessor(uint32_t rule, const Grammar::Target &target, const Successor &successor, const Shape &parent,
                         Vec2f offset, Vec2f size, int depth);
    void split(uint32_t rule, uint32_t branch, const Shape &shape, int depth);
    void repeat(uint32_t rule, uint32_t branch, const Shape &shape, int depth);
    float property(const Successor &successor) const;
    void warnOnce(const Branch &branch, const std::string &message);
    [[noreturn]] void failLimit(uint32_t rule, const std::string &what) const;

    const Grammar &grammar_;
    const BuildingProperties &properties_;
    DerivationSeed seed_;
    std::vector<Terminal> &out_;
    std::vector<std::string> &warnings_;
    DerivationLimits limits_;
    size_t shapes_ = 0;
    std::unordered_set<const Branch *> warned_;
};

float Derivation::property(const Successor &successor) const {
    if (successor.property.empty()) return 1;
    auto value = properties_.number(successor.property);
    if (!value)
        throw InputError(
            successor.loc,
            fmt::format("property '{}' is not set: define it in a <BuildingSettings>", successor.property));
    return *value;
}

void Derivation::warnOnce(const Branch &branch, const std::string &message) {
    if (warned_.insert(&branch).second) warnings_.push_back(fmt::format("{}: {}", branch.loc.toString(), message));
}

void Derivation::failLimit(uint32_t rule, const std::string &what) const {
    const Rule &r = grammar_.rules().rules[rule];
    throw InputError(r.loc,
                     fmt::format("deriving '{}' {}; does the rule derive itself without end?", r.predecessor, what));
}

void Derivation::deriveRule(uint32_t rule, const Shape &shape, int depth) {
    if (depth > limits_.maxDepth) failLimit(rule, fmt::format("goes deeper than {} rules", limits_.maxDepth));
    if (++shapes_ > limits_.maxShapes) failLimit(rule, fmt::format("makes more than {} shapes", limits_.maxShapes));
    const Rule &r = grammar_.rules().rules[rule];
    uint32_t b = pickBranch(grammar_.probabilities(rule), branchVariate(seed_, grammar_.ruleKey(rule)),
                            [&](uint32_t i) { return r.branches[i].condition.holdsFor(shape.size.x, shape.size.y); });
    if (b == kNone) return;  // no branch fits this scope: the shape stays empty
    const Branch &branch = r.branches[b];
    switch (branch.kind) {
    case Branch::Kind::Substitution:
        for (uint32_t s = 0; s < branch.successors.size(); ++s)
            deriveSuccessor(rule, grammar_.target(rule, b, s), branch.successors[s], shape, {0, 0}, shape.size, depth);
        break;
    case Branch::Kind::Split: split(rule, b, shape, depth); break;
    case Branch::Kind::Repeat: repeat(rule, b, shape, depth); break;
    }
}

// Places a successor's scope at `offset` (of its centre from the parent's centre) with `size`,
// applies its translate and scale, and derives it or emits it as a terminal.
void Derivation::deriveSuccessor(uint32_t rule, const Grammar::Target &target, const Successor &successor,
                                 const Shape &parent, Vec2f offset, Vec2f size, int depth) {
    if (size.x <= 0 || size.y <= 0) return;
    Shape child;
    Vec3f translation = Vec3f(offset.x, offset.y, 0) + successor.translate;
    child.toFacade = parent.toFacade * Transform::translate(translation) * Transform::scale(successor.scale);
    child.size = size;
    child.texture = successor.texture ? &*successor.texture : parent.texture;
    child.uv = successor.uv ? *successor.uv : parent.uv;
    child.zScale = successor.zScale != ZScale::NotSet ? successor.zScale : parent.zScale;
    if (target.isModel) {
        if (++shapes_ > limits_.maxShapes) failLimit(rule, fmt::format("makes more than {} shapes", limits_.maxShapes));
        out_.push_back({target.index, child.toFacade, child.size, child.texture, child.uv, child.zScale, rule});
        return;
    }
    deriveRule(target.index, child, depth + 1);
}

float &along(Vec2f &v, SplitAxis axis) { return axis == SplitAxis::Right ? v.x : v.y; }

void Derivation::split(uint32_t rule, uint32_t b, const Shape &shape, int depth) {
    const Branch &branch = grammar_.rules().rules[rule].branches[b];
    Vec2f scopeSize = shape.size;
    float length = along(scopeSize, branch.axis);
    float absolute = 0, relative = 0;
    for (const Successor &s : branch.successors) {
        if (s.size.unit == Extent::Unit::Relative) relative += s.size.value;
        else absolute += s.size.value * property(s);
    }
    if (absolute > length * (1 + 1e-5f) + 1e-5f)
        warnOnce(branch,
                 fmt::format("the absolute sizes ({:.3g} m) exceed the scope ({:.3g} m); the shapes overlap", absolute,
                             length));
    float perRelative = relative > 0 ? std::max(length - absolute, 0.0f) / relative : 0.0f;
    float position = 0;
    for (uint32_t s = 0; s < branch.successors.size(); ++s) {
        const Successor &successor = branch.successors[s];
        float extent = successor.size.unit == Extent::Unit::Relative ? successor.size.value * perRelative
                                                                     : successor.size.value * property(successor);
        Vec2f size = shape.size, offset{0, 0};
        along(size, branch.axis) = extent;
        along(offset, branch.axis) = -length / 2 + position + extent / 2;
        position += extent;
        deriveSuccessor(rule, grammar_.target(rule, b, s), successor, shape, offset, size, depth);
    }
}

// count = ⌊L/g⌋ tiles of L/count (L434); a scope shorter than one tile holds one tile of its
// own length. A floating size takes the count whose tile comes closest to g.
// The ratio has been checked against the shape limit, so the counts fit an int.
int repeatCount(float length, float tile, Extent::Unit unit) {
    float ratio = length / tile;
    if (unit != Extent::Unit::Floating) return std::max(1, int(std::floor(ratio + 1e-4f)));
    int below = std::max(1, int(std::floor(ratio))), above = below + 1;
    return std::abs(length / float(above) - tile) < std::abs(length / float(below) - tile) ? above : below;
}

void Derivation::repeat(uint32_t rule, uint32_t b, const Shape &shape, int depth) {
    const Branch &branch = grammar_.rules().rules[rule].branches[b];
    Vec2f scopeSize = shape.size;
    float length = along(scopeSize, branch.axis);
    float tile = branch.repeatSize.value * property(branch.successors.front());
    if (!(tile > 0))
        throw InputError(branch.loc, fmt::format("the repeat's tile size is {} m; it must be positive", tile));
    if (length / tile > float(limits_.maxShapes))
        throw InputError(branch.loc,
                         fmt::format("a {:.3g} m tile repeated over {:.3g} m makes more than {} shapes", tile, length,
                                     limits_.maxShapes));
    int count = repeatCount(length, tile, branch.repeatSize.unit);
    float extent = length / float(count);
    for (int i = 0; i < count; ++i) {
        Vec2f size = shape.size, offset{0, 0};
        along(size, branch.axis) = extent;
        along(offset, branch.axis) = -length / 2 + (float(i) + 0.5f) * extent;
        for (uint32_t s = 0; s < branch.successors.size(); ++s)
            deriveSuccessor(rule, grammar_.target(rule, b, s), branch.successors[s], shape, offset, size, depth);
    }
}

}  // namespace

uint32_t chooseBranch(const Grammar &grammar, const DerivationSeed &seed, uint32_t rule) {
    return pickBranch(grammar.probabilities(rule), branchVariate(seed, grammar.ruleKey(rule)),
                      [](uint32_t) { return true; });
}

void deriveFacade(const Grammar &grammar, const std::string &startSymbol, Vec2f size,
                  const BuildingProperties &properties, const DerivationSeed &seed, std::vector<Terminal> &out,
                  std::vector<std::string> &warnings, const DerivationLimits &limits) {
    auto rule = grammar.findRule(startSymbol);
    if (!rule)
        throw InputError(FileLoc{grammar.rules().name, 0, 0},
                         fmt::format("the rule set has no rule for the start symbol '{}'", startSymbol));
    Shape start;
    start.toFacade = Transform::translate({size.x / 2, size.y / 2, 0});
    start.size = size;
    Derivation(grammar, properties, seed, out, warnings, limits).deriveRule(*rule, start, 0);
}

}  // namespace veduta
