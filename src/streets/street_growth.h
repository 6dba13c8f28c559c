// Growing a word graph by its rules (Goitowski 2010, §4.2.2 and §4.2.5, Listing 4.1): the
// placeholder of lowest iteration depth inside the window is expanded first, ties by id, so
// that older areas are never more detailed than newer ones. The geometry (the constraints, the
// street graph) comes in through the NodeQuery and an ExpansionObserver (street_builder.h).
#pragma once

#include <functional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/vecmath.h"
#include "streets/lsystem.h"
#include "streets/word_graph.h"

namespace veduta {

// The part of the ground plane (veduta's xy) where placeholders are expanded.
struct GrowthWindow {
    Vec2f centre;
    float radius = 0;
    bool contains(const Vec3f &position) const;
};

// What one grow() call may do before it stops with the limit's GrowthStop. By default the
// bound of a rewrite's words: a rule such as `A -> A` expands forever without adding a node.
struct GrowthLimits {
    size_t maxExpansions = kMaxRewrittenWords;
    size_t maxNodes = kMaxRewrittenWords;  // the graph never passes it
};

enum class GrowthStop {
    Exhausted,       // no placeholder left inside the window
    ExpansionLimit,  // maxExpansions expansions done
    NodeLimit,       // the next expansion would pass maxNodes; it is left for a later call
};

// Answers a rule's query for the node being expanded: lsystem.h's StreetQuery with the asking
// node, whose turtle the proposed street starts from.
using NodeQuery = std::function<QueryResult(const WordNode &asking, char kind, std::span<float> inOut)>;

// Told of every expansion, so that it can build what the new words draw; it may cut a node off,
// and a placeholder cut off is never expanded.
class ExpansionObserver {
  public:
    virtual ~ExpansionObserver() = default;
    // `placeholder` was replaced: its id now holds the successor's first word and the others
    // are the nodes from `firstNew` to the graph's end.
    virtual void expanded(NodeId placeholder, NodeId firstNew) = 0;
    virtual bool isCutOff(NodeId id) const = 0;
};

struct GrowthResult {
    GrowthStop stop = GrowthStop::Exhausted;
    size_t expansions = 0;
};

class StreetGrowth {
  public:
    // The graph, the rules, the draws and the observer must outlive the growth.
    StreetGrowth(WordGraph &graph, std::span<const StreetRule> rules, NodeQuery query, RandomDraws &draws,
                 ExpansionObserver *observer = nullptr);

    // Expands placeholders until none is left inside `window` or a limit is reached. A
    // placeholder outside the window waits for a later call; one that no rule applies to
    // (or whose successor is empty) stays as it is and is not tried again.
    GrowthResult grow(const GrowthWindow &window, const GrowthLimits &limits);

    // The placeholders not expanded yet, inside the window or not.
    size_t pendingCount() const { return pending_.size(); }
    // Each distinct warning of the rule choice (lsystem.h's expandWord), once.
    const std::vector<std::string> &warnings() const { return warnings_; }

  private:
    void queueIfPlaceholder(NodeId id);

    WordGraph &graph_;
    std::span<const StreetRule> rules_;
    NodeQuery query_;
    RandomDraws &draws_;
    ExpansionObserver *observer_;
    std::set<std::pair<uint32_t, NodeId>> pending_;  // (depth, id): lowest depth, then id first
    std::vector<std::string> warnings_;
};

}  // namespace veduta
