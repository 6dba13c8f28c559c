#include "streets/street_growth.h"

#include <algorithm>

namespace veduta {

bool GrowthWindow::contains(const Vec3f &position) const {
    Vec2f offset = Vec2f{position.x, position.y} - centre;
    return dot(offset, offset) <= radius * radius;
}

StreetGrowth::StreetGrowth(WordGraph &graph, std::span<const StreetRule> rules, NodeQuery query, RandomDraws &draws,
                           ExpansionObserver *observer) :
    graph_(graph), rules_(rules), query_(std::move(query)), draws_(draws), observer_(observer) {
    for (NodeId id = 0; id < graph_.size(); ++id) queueIfPlaceholder(id);
}

GrowthResult StreetGrowth::grow(const GrowthWindow &window, const GrowthLimits &limits) {
    GrowthResult result;
    std::vector<std::pair<uint32_t, NodeId>> outside;
    while (!pending_.empty()) {
        auto [depth, id] = pending_.extract(pending_.begin()).value();
        if (observer_ && observer_->isCutOff(id)) continue;
        if (!window.contains(graph_.node(id).turtle.position)) {
            outside.emplace_back(depth, id);
            continue;
        }
        if (result.expansions == limits.maxExpansions) {
            pending_.emplace(depth, id);
            result.stop = GrowthStop::ExpansionLimit;
            break;
        }
        // Contexts are not looked up on the tree (docs/street-rules.md): the word stands alone.
        // The node's id names it for the draws, so they depend on the seed, the id and the index.
        WordDraws draws(draws_, id);
        StreetQuery query;
        // A copy of the id: clang 14 (the fuzz build) cannot capture a structured binding.
        if (query_)
            query = [this, asking = id](char kind, std::span<float> inOut) {
                return query_(graph_.node(asking), kind, inOut);
            };
        std::optional<std::vector<Word>> successor =
            expandWord(std::span(&graph_.node(id).word, 1), 0, rules_, draws, query, warnings_);
        if (!successor || successor->empty()) continue;
        if (graph_.size() + successor->size() - 1 > limits.maxNodes) {
            pending_.emplace(depth, id);
            result.stop = GrowthStop::NodeLimit;
            break;
        }
        NodeId firstNew = NodeId(graph_.size());
        graph_.expand(id, *successor);
        ++result.expansions;
        if (observer_) observer_->expanded(id, firstNew);
        queueIfPlaceholder(id);
        for (NodeId added = firstNew; added < graph_.size(); ++added) queueIfPlaceholder(added);
    }
    pending_.insert(outside.begin(), outside.end());
    return result;
}

void StreetGrowth::queueIfPlaceholder(NodeId id) {
    if (observer_ && observer_->isCutOff(id)) return;
    const WordNode &node = graph_.node(id);
    std::span<const Word> word(&node.word, 1);
    if (std::ranges::any_of(rules_, [&](const StreetRule &rule) { return headMatches(rule, word, 0); }))
        pending_.emplace(node.depth, id);
}

}  // namespace veduta
