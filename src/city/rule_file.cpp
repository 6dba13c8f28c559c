#include "city/rule_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "city/building_settings.h"
#include "core/check.h"
#include "core/input_file.h"
#include "io/xml_reader.h"

namespace veduta {

namespace {

// Bilke's own files write thirds as 0.333333.
constexpr float kProbabilitySumTolerance = 1e-4f;

constexpr const char *kWhiteSpace = " \t\r\n";

std::optional<float> parseFloat(std::string_view text) {
    float value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::vector<pugi::xml_node> childElements(pugi::xml_node node) {
    std::vector<pugi::xml_node> children;
    for (pugi::xml_node child : node.children()) {
        if (child.type() == pugi::node_element) children.push_back(child);
    }
    return children;
}

// Bilke's files break symbol names across lines, so the text is trimmed; white space
// inside a name is more likely two names run together than a name.
std::string symbolName(const XmlElement &e) {
    std::string name = e.text();
    if (name.empty()) e.fail(fmt::format("<{}> holds no symbol name", e.name()));
    if (name.find_first_of(kWhiteSpace) != std::string::npos) {
        e.fail(fmt::format("'{}' is not a symbol name: it contains white space", name));
    }
    return name;
}

// "4" metres, "1r" a share of what the absolute sizes leave, "~2.1" a floating repeat size.
Extent readExtent(const XmlElement &e, const char *attribute) {
    std::string text = trimmedXmlText(e.string(attribute));
    Extent extent;
    std::string_view number = text;
    if (number.starts_with('~')) {
        extent.unit = Extent::Unit::Floating;
        number.remove_prefix(1);
    } else if (number.ends_with('r')) {
        extent.unit = Extent::Unit::Relative;
        number.remove_suffix(1);
    } else {
        extent.unit = Extent::Unit::Absolute;
    }
    std::optional<float> value = parseFloat(number);
    if (!value) {
        e.failAt(attribute,
                 fmt::format("'{}' is not a size: give metres ('4'), a share ('1r') or a floating "
                             "repeat size ('~2.1')",
                             text));
    }
    if (*value <= 0) e.failAt(attribute, fmt::format("size '{}' is not positive", text));
    extent.value = *value;
    return extent;
}

SplitAxis readAxis(const XmlElement &e) {
    std::string axis = trimmedXmlText(e.string("axis"));
    if (axis == "r") return SplitAxis::Right;
    if (axis == "u") return SplitAxis::Up;
    e.failAt("axis", fmt::format("unknown axis '{}': expected r (right) or u (up)", axis));
}

ZScale readZScale(const XmlElement &e) {
    if (!e.has("z_scale")) return ZScale::NotSet;
    std::string mode = trimmedXmlText(e.string("z_scale"));
    if (mode == "none") return ZScale::None;
    if (mode == "right") return ZScale::Right;
    if (mode == "up") return ZScale::Up;
    if (mode == "average") return ZScale::Average;
    e.failAt("z_scale", fmt::format("unknown z_scale '{}': expected none, right, up or average", mode));
}

std::optional<Vec2f> readUv(const XmlElement &e) {
    if (!e.has("uv")) return std::nullopt;
    std::vector<float> uv = e.numbers("uv");
    if (uv.size() != 2) e.failAt("uv", "attribute 'uv' takes two numbers");
    if (uv[0] <= 0 || uv[1] <= 0) e.failAt("uv", "the uv scale must be positive");
    return Vec2f{uv[0], uv[1]};
}

// Bilke 2009 was written on Windows: its texture paths use '\'.
std::string texturePath(std::string path) {
    std::replace(path.begin(), path.end(), '\\', '/');
    return path;
}

float readProbability(const XmlElement &e) {
    if (!e.has("value")) e.fail("<Probability> needs the attribute 'value'");
    float probability = e.number("value", 0);
    if (probability < 0) e.failAt("value", fmt::format("probability {} is negative", probability));
    return probability;
}

float readBound(const XmlElement &e, const char *attribute, float fallback) {
    float bound = e.number(attribute, fallback);
    if (bound < 0) e.failAt(attribute, fmt::format("attribute '{}' is {}, which is negative", attribute, bound));
    return bound;
}

ScopeCondition readCondition(const XmlElement &e) {
    ScopeCondition c;
    c.minWidth = readBound(e, "min_width", c.minWidth);
    c.maxWidth = readBound(e, "max_width", c.maxWidth);
    c.minHeight = readBound(e, "min_height", c.minHeight);
    c.maxHeight = readBound(e, "max_height", c.maxHeight);
    if (c.minWidth > c.maxWidth) {
        e.failAt("max_width", fmt::format("max_width {} is less than min_width {}", c.maxWidth, c.minWidth));
    }
    if (c.minHeight > c.maxHeight) {
        e.failAt("max_height", fmt::format("max_height {} is less than min_height {}", c.maxHeight, c.minHeight));
    }
    return c;
}

void readSplitOrRepeat(const XmlElement &e, Branch &branch) {
    branch.kind = e.name() == "Split" ? Branch::Kind::Split : Branch::Kind::Repeat;
    branch.axis = readAxis(e);
    if (branch.kind == Branch::Kind::Repeat) {
        if (!e.has("size")) e.fail("<Repeat> needs the attribute 'size'");
        branch.repeatSize = readExtent(e, "size");
        if (branch.repeatSize.unit == Extent::Unit::Relative) {
            e.failAt("size", "a repeat's size is absolute ('2') or floating ('~2'), not relative");
        }
    }
    e.checkLeaf();
}

// The rules of one file and of the files it includes, gathered into one RuleSet.
class RuleSetReader {
  public:
    RuleSetReader(const IsModelName &isModel, const RuleFileLimits &limits) : isModel_(isModel), limits_(limits) {}

    // `file` is the document's own path, for finding include cycles; empty for text.
    void readTopLevel(const XmlDocument &doc, const std::filesystem::path &file) {
        if (!file.empty()) openFiles_.push_back({std::filesystem::weakly_canonical(file), doc.name()});
        readDocument(doc, file.parent_path(), 0);
    }

    RuleSet finish() &&;

  private:
    struct OpenFile {
        std::filesystem::path canonical;
        std::string name;  // as messages call it
    };

    void readDocument(const XmlDocument &doc, const std::filesystem::path &baseDirectory, int depth) {
        XmlElement root(doc, doc.root());
        if (root.name() != "Rulefile")
            root.fail(fmt::format("the root element is <{}>, expected <Rulefile>", root.name()));
        std::string name = root.string("name");
        if (depth == 0) set_.name = name;
        // The schema references of Bilke's files are accepted and mean nothing to us.
        root.string("xmlns:xsi", "");
        root.string("xsi:noNamespaceSchemaLocation", "");
        root.checkAllRead();
        std::vector<XmlElement> includes;
        for (pugi::xml_node child : childElements(doc.root())) {
            XmlElement e(doc, child);
            if (e.name() == "Rule") {
                addRule(readRule(doc, child));
            } else if (e.name() == "BuildingSettings") {
                readSettings(doc, child);
            } else if (e.name() == "Include") {
                includes.push_back(e);
            } else if (e.name() == "Masonry") {
                readMasonry(e, baseDirectory);
            } else if (e.name() == "Cornice") {
                readCornice(e, baseDirectory);
            } else {
                e.fail(fmt::format("unknown element <{}> in <Rulefile>", e.name()));
            }
        }
        // After the file's own settings, so that the including file's settings win.
        for (const XmlElement &include : includes) readInclude(include, baseDirectory, depth + 1);
    }

    void readInclude(const XmlElement &e, const std::filesystem::path &baseDirectory, int depth) {
        std::filesystem::path file = e.string("file");
        e.checkLeaf();
        if (depth > limits_.maxIncludeDepth) {
            e.fail(fmt::format("includes are nested more than {} deep", limits_.maxIncludeDepth));
        }
        if (file.is_relative()) file = baseDirectory / file;
        std::filesystem::path canonical = std::filesystem::weakly_canonical(file);
        auto open = std::find_if(openFiles_.begin(), openFiles_.end(),
                                 [&](const OpenFile &f) { return f.canonical == canonical; });
        if (open != openFiles_.end()) {
            std::string cycle;
            for (auto it = open; it != openFiles_.end(); ++it) cycle += fmt::format("{} → ", it->name);
            e.failAt("file", fmt::format("the includes form a cycle: {}{}", cycle, file.string()));
        }
        XmlDocument doc = openInclude(e, file);
        openFiles_.push_back({canonical, doc.name()});
        readDocument(doc, file.parent_path(), depth);
        openFiles_.pop_back();
    }

    static XmlDocument openInclude(const XmlElement &e, const std::filesystem::path &file) {
        try {
            return XmlDocument::fromFile(file);
        } catch (const InputError &error) {
            // A file that cannot be opened has no line of its own: point at the include.
            if (error.loc().line == 0) e.failAt("file", error.what());
            throw;
        }
    }

    // <Masonry model="…" facades="…" bricks|ashlar|cyclopean="file" unit="metres"/>, the file
    // beside the rule file; unit (metres per unit of the description) for bricks and ashlar only.
    void readMasonry(const XmlElement &e, const std::filesystem::path &baseDirectory) {
        MasonryRule rule;
        rule.loc = e.loc();
        rule.model = e.string("model");
        std::istringstream facades(e.string("facades", ""));
        for (std::string facade; facades >> facade;) rule.facades.push_back(facade);
        const char *kinds[] = {"bricks", "ashlar", "cyclopean"};
        const char *given = nullptr;
        for (const char *kind : kinds)
            if (e.has(kind)) {
                if (given) e.failAt(kind, fmt::format("<Masonry> gives both {}= and {}=", given, kind));
                given = kind;
            }
        if (!given) e.fail("<Masonry> needs one of bricks=, ashlar= or cyclopean=");
        std::filesystem::path file = e.string(given);
        if (file.is_relative()) file = baseDirectory / file;
        std::string text = readDescription(e, given, file);
        MasonryStyle &style = rule.style;
        style.loc = rule.loc;
        style.source = descriptionHash(text);
        if (std::string_view(given) == "cyclopean") {
            style.kind = MasonryStyle::Kind::Cyclopean;
            style.cyclopean = std::make_shared<const CyclopeanMasonry>(parseCyclopeanMasonry(text, file.string()));
        } else {
            style.metresPerUnit = e.number("unit", 1.0f, 1e-6f, 100.0f);
            if (std::string_view(given) == "bricks") {
                style.kind = MasonryStyle::Kind::Bricks;
                style.bricks = std::make_shared<const BrickBond>(parseBrickBond(text, file.string()));
            } else {
                style.kind = MasonryStyle::Kind::Ashlar;
                style.ashlar = std::make_shared<const AshlarMasonry>(parseAshlarMasonry(text, file.string()));
            }
        }
        e.checkLeaf();
        set_.masonry.push_back(std::move(rule));
    }

    // <Cornice model="…" rules="…" profile="file"/>, the file beside the rule file.
    void readCornice(const XmlElement &e, const std::filesystem::path &baseDirectory) {
        CorniceRule rule;
        rule.loc = e.loc();
        rule.model = e.string("model");
        std::istringstream rules(e.string("rules", ""));
        for (std::string name; rules >> name;) rule.rules.push_back(name);
        std::filesystem::path file = e.string("profile");
        if (file.is_relative()) file = baseDirectory / file;
        rule.cornice = std::make_shared<const CorniceDescription>(
            parseCorniceDescription(readDescription(e, "profile", file), file.string()));
        rule.directory = file.parent_path();
        e.checkLeaf();
        set_.cornices.push_back(std::move(rule));
    }

    // A description file's text; one that cannot be read is said at the attribute naming it.
    static std::string readDescription(const XmlElement &e, const char *attribute, const std::filesystem::path &file) {
        try {
            return readInputFile(file);
        } catch (const InputError &error) {
            if (error.loc().line == 0) e.failAt(attribute, error.what());
            throw;
        }
    }

    void readSettings(const XmlDocument &doc, pugi::xml_node node) {
        for (auto &[name, value] : readBuildingSettings(XmlElement(doc, node))) set_.settings.try_emplace(name, value);
    }

    Rule readRule(const XmlDocument &doc, pugi::xml_node node) {
        XmlElement e(doc, node);
        e.checkAllRead();
        Rule rule;
        rule.loc = e.loc();
        bool hasPredecessor = false, hasRules = false;
        for (pugi::xml_node child : childElements(node)) {
            XmlElement c(doc, child);
            if (c.name() == "Predecessor" && !hasPredecessor) {
                c.checkLeaf();
                rule.predecessor = symbolName(c);
                // A rule cannot take a model's name: which of the two a successor means would be
                // anyone's guess.
                if (isModel_(rule.predecessor))
                    c.fail(fmt::format("'{}' is a model's name; a rule needs a name of its own", rule.predecessor));
                hasPredecessor = true;
            } else if (c.name() == "Rules" && !hasRules) {
                c.checkAllRead();
                rule.branches = readBranches(doc, child);
                hasRules = true;
            } else if (c.name() == "Predecessor" || c.name() == "Rules") {
                c.fail(fmt::format("<Rule> holds a second <{}>", c.name()));
            } else {
                c.fail(fmt::format("unknown element <{}> in <Rule>", c.name()));
            }
        }
        if (!hasPredecessor) e.fail("<Rule> needs a <Predecessor>");
        if (rule.branches.empty()) e.fail(fmt::format("rule '{}' has no <Probability> branch", rule.predecessor));
        normaliseProbabilities(rule);
        return rule;
    }

    std::vector<Branch> readBranches(const XmlDocument &doc, pugi::xml_node node) {
        std::vector<Branch> branches;
        for (pugi::xml_node child : childElements(node)) {
            XmlElement c(doc, child);
            if (c.name() != "Probability") c.fail(fmt::format("unknown element <{}> in <Rules>", c.name()));
            branches.push_back(readBranch(doc, child));
        }
        return branches;
    }

    Branch readBranch(const XmlDocument &doc, pugi::xml_node node) {
        XmlElement e(doc, node);
        Branch branch;
        branch.loc = e.loc();
        branch.probability = readProbability(e);
        branch.condition = readCondition(e);
        e.checkAllRead();
        for (pugi::xml_node child : childElements(node)) {
            XmlElement c(doc, child);
            if (c.name() == "Split" || c.name() == "Repeat") {
                if (branch.kind != Branch::Kind::Substitution || !branch.successors.empty()) {
                    c.fail(fmt::format("<{}> can only be the first element of <Probability>", c.name()));
                }
                readSplitOrRepeat(c, branch);
            } else if (c.name() == "Symbol") {
                branch.successors.push_back(readSuccessor(c, branch.kind));
            } else {
                c.fail(fmt::format("unknown element <{}> in <Probability>", c.name()));
            }
        }
        if (branch.successors.empty()) e.fail("the branch has no <Symbol>");
        return branch;
    }

    Successor readSuccessor(const XmlElement &e, Branch::Kind kind) {
        Successor s;
        s.name = symbolName(e);
        s.loc = e.loc();
        if (e.has("size")) {
            Extent size = readExtent(e, "size");
            if (size.unit == Extent::Unit::Floating) {
                e.failAt("size", "a floating size ('~') is for <Repeat>, not <Symbol>");
            }
            if (kind == Branch::Kind::Split) {
                s.size = size;
            } else {
                warn(e.attributeLoc("size"), "'size' has no effect outside a split; it is ignored");
            }
        }
        s.property = trimmedXmlText(e.string("property", ""));
        if (e.has("texture")) s.texture = texturePath(trimmedXmlText(e.string("texture")));
        s.scale = e.vec3("scale", s.scale);
        // A negative scale mirrors; a zero one would flatten the shape into nothing and leave its
        // normals undefined.
        if (std::abs(s.scale.x) < 1e-6f || std::abs(s.scale.y) < 1e-6f || std::abs(s.scale.z) < 1e-6f)
            e.failAt("scale", "a scale of 0 flattens the shape to nothing; use a small number");
        s.translate = e.vec3("translate", s.translate);
        s.uv = readUv(e);
        s.zScale = readZScale(e);
        e.checkLeaf();
        return s;
    }

    // Branches are drawn by their share of the sum, so the derivation never sees the file's
    // rounding (3 × 0.333333); a sum that is clearly not 1 is a slip worth a warning.
    void normaliseProbabilities(Rule &rule) {
        float sum = 0;
        for (const Branch &b : rule.branches) sum += b.probability;
        if (sum == 0)
            throw InputError(rule.loc, fmt::format("the probabilities of rule '{}' are all 0", rule.predecessor));
        if (std::abs(sum - 1) > kProbabilitySumTolerance) {
            warn(rule.loc,
                 fmt::format("the probabilities of rule '{}' sum to {}, not 1; they are scaled to sum to 1",
                             rule.predecessor, sum));
        }
        for (Branch &b : rule.branches) b.probability /= sum;
    }

    void addRule(Rule rule) {
        auto [it, added] = set_.ruleIndex.try_emplace(rule.predecessor, uint32_t(set_.rules.size()));
        if (!added) {
            throw InputError(rule.loc,
                             fmt::format("rule '{}' is defined twice: first at {}", rule.predecessor,
                                         set_.rules[it->second].loc.toString()));
        }
        set_.rules.push_back(std::move(rule));
    }

    void warn(const FileLoc &loc, const std::string &message) {
        set_.warnings.push_back(fmt::format("{}: {}", loc.toString(), message));
    }

    const IsModelName &isModel_;
    RuleFileLimits limits_;
    RuleSet set_;
    std::vector<OpenFile> openFiles_;  // the file being read and those that include it
};

// Which rules can derive into models alone, and, for those that cannot, why. Both questions
// are answered in time linear in the size of the rules: a chain of 30,000 rules is a
// file users' generators write.
class TerminationCheck {
  public:
    TerminationCheck(const RuleSet &set, const IsModelName &isModel) :
        set_(set), isModel_(isModel), finishes_(set.rules.size(), false) {
        findFinishingRules();
    }

    // Throws for the first rule, in file order, that cannot finish and lies on a cycle of
    // such rules: every rule that cannot finish leads to one, and the cycle is the cause.
    void check() const {
        std::vector<bool> onCycle = rulesOnStuckCycles();
        for (uint32_t i = 0; i < set_.rules.size(); ++i)
            if (onCycle[i]) throw InputError(set_.rules[i].loc, neverFinishes(set_.rules[i], cycleThrough(i)));
    }

  private:
    // A model finishes, and a rule does once one of its branches has only successors that
    // finish. Each branch counts its successors not yet known to finish; a rule found to
    // finish counts down the branches that derive it, once.
    void findFinishingRules() {
        constexpr uint32_t kNever = 1u << 31;  // a successor that is neither a model nor a rule
        struct BranchOf {
            uint32_t rule, branch;
        };
        std::vector<std::vector<uint32_t>> open(set_.rules.size());
        std::vector<std::vector<BranchOf>> derivedBy(set_.rules.size());
        std::deque<uint32_t> finished;
        auto finish = [&](uint32_t rule) {
            if (finishes_[rule]) return;
            finishes_[rule] = true;
            finished.push_back(rule);
        };
        for (uint32_t i = 0; i < set_.rules.size(); ++i) {
            const Rule &rule = set_.rules[i];
            open[i].assign(rule.branches.size(), 0);
            for (uint32_t b = 0; b < rule.branches.size(); ++b) {
                for (const Successor &s : rule.branches[b].successors) {
                    if (isModel_(s.name)) continue;
                    auto it = set_.ruleIndex.find(s.name);
                    if (it == set_.ruleIndex.end()) {
                        open[i][b] = kNever;
                        break;
                    }
                    ++open[i][b];
                    derivedBy[it->second].push_back({i, b});
                }
                if (open[i][b] == 0) finish(i);
            }
        }
        while (!finished.empty()) {
            uint32_t rule = finished.front();
            finished.pop_front();
            for (BranchOf of : derivedBy[rule])
                if (--open[of.rule][of.branch] == 0) finish(of.rule);
        }
    }

    bool finishes(const Successor &s) const {
        if (isModel_(s.name)) return true;
        auto it = set_.ruleIndex.find(s.name);
        return it != set_.ruleIndex.end() && finishes_[it->second];
    }

    // The rules that rule i derives in any branch and that cannot finish.
    std::vector<uint32_t> stuckSuccessors(uint32_t i) const {
        std::vector<uint32_t> stuck;
        for (const Branch &b : set_.rules[i].branches) {
            for (const Successor &s : b.successors) {
                if (!finishes(s)) stuck.push_back(set_.ruleIndex.at(s.name));
            }
        }
        return stuck;
    }

    // The rules that cannot finish and lie on a cycle of such rules: those in a strongly
    // connected component of more than one rule, or that derive themselves (Kosaraju's two
    // depth-first searches, with stacks of their own rather than recursion).
    std::vector<bool> rulesOnStuckCycles() const {
        size_t n = set_.rules.size();
        std::vector<std::vector<uint32_t>> forward(n), backward(n);
        for (uint32_t i = 0; i < n; ++i) {
            if (finishes_[i]) continue;
            for (uint32_t next : stuckSuccessors(i)) {
                forward[i].push_back(next);
                backward[next].push_back(i);
            }
        }
        std::vector<uint32_t> order;  // by the time each search left the rule
        std::vector<bool> seen(n, false);
        for (uint32_t root = 0; root < n; ++root) {
            if (finishes_[root] || seen[root]) continue;
            std::vector<std::pair<uint32_t, size_t>> stack{{root, 0}};
            seen[root] = true;
            while (!stack.empty()) {
                auto &[rule, edge] = stack.back();
                if (edge < forward[rule].size()) {
                    uint32_t next = forward[rule][edge++];
                    if (!seen[next]) {
                        seen[next] = true;
                        stack.push_back({next, 0});
                    }
                } else {
                    order.push_back(rule);
                    stack.pop_back();
                }
            }
        }
        constexpr uint32_t kNone = ~0u;
        std::vector<uint32_t> component(n, kNone);
        std::vector<uint32_t> size;
        for (auto it = order.rbegin(); it != order.rend(); ++it) {
            if (component[*it] != kNone) continue;
            auto id = uint32_t(size.size());
            size.push_back(0);
            std::vector<uint32_t> stack{*it};
            component[*it] = id;
            while (!stack.empty()) {
                uint32_t rule = stack.back();
                stack.pop_back();
                ++size[id];
                for (uint32_t previous : backward[rule]) {
                    if (component[previous] != kNone) continue;
                    component[previous] = id;
                    stack.push_back(previous);
                }
            }
        }
        std::vector<bool> onCycle(n, false);
        for (uint32_t i = 0; i < n; ++i) {
            if (finishes_[i]) continue;
            bool self = std::find(forward[i].begin(), forward[i].end(), i) != forward[i].end();
            onCycle[i] = self || size[component[i]] > 1;
        }
        return onCycle;
    }

    // The shortest path from rule `start` back to itself through rules that cannot finish,
    // start included at both ends; `start` lies on such a cycle.
    std::vector<uint32_t> cycleThrough(uint32_t start) const {
        constexpr uint32_t kUnseen = ~0u;
        std::vector<uint32_t> previous(set_.rules.size(), kUnseen);
        std::deque<uint32_t> queue{start};
        while (!queue.empty()) {
            uint32_t i = queue.front();
            queue.pop_front();
            for (uint32_t next : stuckSuccessors(i)) {
                if (next == start) {
                    std::vector<uint32_t> cycle{start};
                    for (uint32_t k = i; k != start; k = previous[k]) cycle.push_back(k);
                    cycle.push_back(start);
                    std::reverse(cycle.begin(), cycle.end());
                    return cycle;
                }
                if (previous[next] == kUnseen) {
                    previous[next] = i;
                    queue.push_back(next);
                }
            }
        }
        VEDUTA_UNREACHABLE("rule on a cycle of stuck rules has no path back to itself");
    }

    std::string neverFinishes(const Rule &rule, const std::vector<uint32_t> &cycle) const {
        bool selfInEveryBranch = std::all_of(rule.branches.begin(), rule.branches.end(), [&](const Branch &b) {
            return std::any_of(b.successors.begin(), b.successors.end(),
                               [&](const Successor &s) { return s.name == rule.predecessor; });
        });
        if (selfInEveryBranch) {
            return fmt::format("rule '{}' can never finish: every branch derives {} again", rule.predecessor,
                               rule.predecessor);
        }
        std::string path = rule.predecessor;
        for (size_t k = 1; k < cycle.size(); ++k) path += fmt::format(" → {}", set_.rules[cycle[k]].predecessor);
        return fmt::format(
            "rule '{}' can never finish: every branch derives a rule that cannot finish, round the "
            "cycle {}",
            rule.predecessor, path);
    }

    const RuleSet &set_;
    const IsModelName &isModel_;
    std::vector<bool> finishes_;
};

RuleSet RuleSetReader::finish() && {
    for (const Rule &rule : set_.rules) {
        for (const Branch &b : rule.branches) {
            for (const Successor &s : b.successors) {
                if (!set_.find(s.name) && !isModel_(s.name)) {
                    throw InputError(
                        s.loc, fmt::format("unknown symbol '{}': no rule derives it and it is not a model", s.name));
                }
            }
        }
    }
    for (const CorniceRule &cornice : set_.cornices) {
        if (!isModel_(cornice.model))
            throw InputError(cornice.loc, fmt::format("<Cornice model=\"{}\">: no such model", cornice.model));
        for (const std::string &rule : cornice.rules)
            if (!set_.find(rule))
                throw InputError(cornice.loc, fmt::format("<Cornice rules=\"…\">: no rule derives '{}'", rule));
    }
    TerminationCheck(set_, isModel_).check();
    return std::move(set_);
}

}  // namespace

RuleSet readRuleFile(const std::filesystem::path &file, const IsModelName &isModel, const RuleFileLimits &limits) {
    RuleSetReader reader(isModel, limits);
    reader.readTopLevel(XmlDocument::fromFile(file), file);
    return std::move(reader).finish();
}

RuleSet parseRuleFile(std::string xmlText, std::string name, const IsModelName &isModel, const RuleFileLimits &limits) {
    RuleSetReader reader(isModel, limits);
    reader.readTopLevel(XmlDocument::fromString(std::move(xmlText), std::move(name)), {});
    return std::move(reader).finish();
}

}  // namespace veduta
