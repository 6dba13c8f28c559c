// The graph whose nodes are the words of a street L-system (Goitowski 2010, §4.2.13): each word
// is a node with its turtle state, brackets make branches, so the words form a tree that grows
// by replacing a placeholder node with the chain of its successor. docs/street-rules.md ("The
// word graph") documents the turtle, the ids and the draw paths.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/vecmath.h"
#include "streets/street_rules.h"

namespace veduta {

using NodeId = uint32_t;
inline constexpr NodeId kNoNode = UINT32_MAX;

// Position and orientation in veduta's frame (z up): heading H, left L, up U, orthonormal.
struct Turtle {
    Vec3f position;
    Vec3f heading{1, 0, 0};
    Vec3f left{0, 1, 0};
    Vec3f up{0, 0, 1};
};

// The turtle after `word`: F, f move; &, +, -, /, \, | turn (degrees, 90 without a parameter);
// everything else, brackets included, leaves it as it is.
Turtle moveTurtle(const Turtle &before, const Word &word);

struct WordNode {
    NodeId id = kNoNode;
    Word word;
    Turtle turtle;       // after the word
    uint32_t depth = 0;  // the iteration that created it: 0 for the initial word
    std::vector<NodeId> predecessors;
    std::vector<NodeId> successors;  // in reading order of the words
    NodeId opener = kNoNode;         // a `]`'s matching `[`: it restores the turtle before that
};

class WordGraph {
  public:
    // The initial word as nodes 0, 1, … at depth 0, from the turtle at the origin.
    explicit WordGraph(std::span<const Word> initialWord);

    const std::vector<WordNode> &nodes() const { return nodes_; }
    const WordNode &node(NodeId id) const { return nodes_.at(id); }
    size_t size() const { return nodes_.size(); }

    // Replaces the placeholder by its (non-empty) successor one iteration deeper: the first
    // word keeps the placeholder's id and predecessors, the others take fresh ids in reading
    // order, and the placeholder's successors hang on the chain's end, re-placed after it.
    void expand(NodeId placeholder, std::span<const Word> successor);

    // The roots and every F node: the ends of the geometric edges.
    bool isDrawNode(NodeId id) const;
    // For each pair of draw nodes joined through non-draw nodes, the path (a, …, b) from a to
    // its successor side b, ordered by (a, b).
    std::vector<std::vector<NodeId>> drawPaths() const;

  private:
    NodeId appendChain(std::span<const Word> words, NodeId first, uint32_t depth);
    NodeId addNode(NodeId attachTo);
    void link(NodeId from, NodeId to);
    void place(NodeId id);
    void placeSubtreesAgain(std::span<const NodeId> roots);
    NodeId predecessorOf(NodeId id) const;

    std::vector<WordNode> nodes_;
};

}  // namespace veduta
