// The street graph a growth builds (Goitowski 2010, §4.2.4–4.2.6, digest §2.5–2.6): it answers a
// rule's ?I and ?E for the node asking, and turns each expansion's F words into streets — as
// proposed, bent onto a vertex, or cut at the street met — cutting off what would have grown
// beyond a street met or a street refused. docs/street-rules.md ("The street builder").
#pragma once

#include <span>
#include <vector>

#include "core/vecmath.h"
#include "streets/street_constraints.h"
#include "streets/street_graph.h"
#include "streets/street_growth.h"
#include "streets/word_graph.h"

namespace veduta {

// The ground's say in a street: water, forest or a slope too steep, sampled by whoever knows the
// terrain and the map (a layer above this one). It answers the ?E query, and it stops every
// street the builder draws, as a street met does.
class StreetEnvironment {
  public:
    virtual ~StreetEnvironment() = default;
    // How far a street from `start` along unit `direction` may run, at most `length`, before it
    // meets ground it must not cross: `length` where nothing stops it.
    virtual float freeLength(const Vec3f &start, const Vec3f &direction, float length) const = 0;
};

// What the F words came to, one count per word drawn or refused.
struct StreetCounts {
    size_t proposed = 0;  // built as proposed (NORMAL)
    size_t snapped = 0;   // ended on an existing vertex (NN, or led to the end of a street met)
    size_t split = 0;     // ended on a street met, which was cut there
    size_t refused = 0;   // no street: FAILED, and the words after it cut off
    size_t stopped = 0;   // ended where the ground stops it (StreetEnvironment), nothing beyond
};

class StreetBuilder final : public ExpansionObserver {
  public:
    // The word graph's root is the first vertex. `roads`, polylines in the ground plane, are the
    // streets already there (an ATKIS or OSM road network): static vertices and edges, seeded
    // before the initial word is drawn, which the rules' streets meet as any other street (they
    // snap to them, end on them or cut them), so that a town grows onto the roads it is given.
    // Consecutive road points closer than a millimetre are one; roads join where they share a
    // point. The words, and the environment when there is one, must outlive the builder.
    explicit StreetBuilder(const WordGraph &words, const StreetConstraints &constraints = {},
                           const StreetEnvironment *environment = nullptr,
                           std::span<const std::vector<Vec2f>> roads = {});

    // ?I(angle, length, result) and ?E(…): the street the asking node's `&(angle)F(length)`
    // would draw, tried against the graph or the ground; corrects angle and length.
    QueryResult query(const WordNode &asking, char kind, std::span<float> inOut);
    NodeQuery nodeQuery();

    void expanded(NodeId placeholder, NodeId firstNew) override;
    bool isCutOff(NodeId id) const override;

    const StreetGraph &graph() const { return graph_; }
    // The vertex a draw node ended on; kNoVertex for other nodes and refused F words.
    VertexId vertexOf(NodeId id) const;
    const StreetCounts &counts() const { return counts_; }

  private:
    // An ?I answer, kept until its expansion has drawn. Every rule asking for the same node
    // gets it, as in the thesis' query cache (several rules test the same street), and the F
    // the chosen rule writes is built as answered.
    struct Answer {
        NodeId asking;
        std::vector<float> inOut;  // corrected
        QueryResult code;
        Vec3f heading;     // of the corrected street
        size_t graphSize;  // vertices + edges when it was given: a change voids it
        SegmentPlan plan;
    };

    size_t graphSize() const { return graph_.vertices().size() + graph_.edges().size(); }
    QueryResult queryGraph(const WordNode &asking, std::span<float> inOut);
    QueryResult queryGround(const WordNode &asking, std::span<float> inOut) const;
    SegmentStart startOf(NodeId id, const Vec3f &position) const;
    void draw(NodeId placeholder, const WordNode &f);
    void addRoad(std::span<const Vec2f> road);
    SegmentPlan planFor(NodeId placeholder, const SegmentStart &start, const WordNode &f) const;
    void limitByGround(const Vec3f &from, SegmentPlan &plan) const;
    void cutOff(NodeId id);
    void cutOffBeyond(NodeId id);

    const WordGraph &words_;
    StreetConstraints constraints_;
    const StreetEnvironment *environment_;
    StreetGraph graph_;
    std::vector<VertexId> vertexOf_;  // per word node
    std::vector<bool> cutOff_;        // per word node
    std::vector<Answer> answers_;
    StreetCounts counts_;
};

}  // namespace veduta
