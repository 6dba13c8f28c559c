#include "streets/word_graph.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace veduta {

namespace {

// Turns `a` towards `b` by `degrees` in their plane, keeping the pair orthonormal.
void turn(Vec3f &a, Vec3f &b, float degrees) {
    float c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    Vec3f turned = a * c + b * s;
    b = b * c - a * s;
    a = turned;
}

float firstParameterOr(const Word &word, float fallback) {
    return word.parameters.empty() ? fallback : word.parameters[0];
}

}  // namespace

Turtle moveTurtle(const Turtle &before, const Word &word) {
    Turtle turtle = before;
    float angle = firstParameterOr(word, 90);
    switch (word.symbol) {
    case 'F':
    case 'f': turtle.position += turtle.heading * firstParameterOr(word, 1); break;
    // The street rules' in-plane turn (digest §2.1), about U, positive to the right (clockwise
    // seen from above): so the thesis' coordinates (Y up) are these, turned Y up → Z up (its
    // &(−90) branch ends at (12.5, 0, −16.1), here at (12.5, 16.1, 0)).
    case '&': turn(turtle.heading, turtle.left, -angle); break;
    case '+': turn(turtle.heading, turtle.up, angle); break;
    case '-': turn(turtle.heading, turtle.up, -angle); break;
    case '/': turn(turtle.left, turtle.up, angle); break;
    case '\\': turn(turtle.left, turtle.up, -angle); break;
    case '|':
        turtle.heading = -turtle.heading;
        turtle.left = -turtle.left;
        break;
    default: break;  // S, P, …, the brackets, ^ and ! neither move nor turn
    }
    return turtle;
}

WordGraph::WordGraph(std::span<const Word> initialWord) {
    if (initialWord.empty()) return;
    appendChain(initialWord, addNode(kNoNode), 0);
}

void WordGraph::expand(NodeId placeholder, std::span<const Word> successor) {
    if (successor.empty()) throw std::invalid_argument("an empty successor cannot replace a node");
    std::vector<NodeId> followers = std::exchange(nodes_.at(placeholder).successors, {});
    NodeId end = appendChain(successor, placeholder, nodes_[placeholder].depth + 1);
    for (NodeId follower : followers) {
        std::erase(nodes_[follower].predecessors, placeholder);
        if (end != kNoNode) link(end, follower);
    }
    // The chain may have moved the turtle, and what followed the placeholder moves with it.
    placeSubtreesAgain(followers);
}

bool WordGraph::isDrawNode(NodeId id) const {
    const WordNode &node = nodes_.at(id);
    return node.predecessors.empty() || node.word.symbol == 'F';
}

std::vector<std::vector<NodeId>> WordGraph::drawPaths() const {
    std::vector<std::vector<NodeId>> paths;
    std::vector<NodeId> path;
    // Explicit stack: a long run of non-draw words must not exhaust the call stack.
    std::vector<std::pair<NodeId, size_t>> stack;  // a node and its place on the path
    for (const WordNode &start : nodes_) {
        if (!isDrawNode(start.id)) continue;
        path = {start.id};
        for (NodeId next : start.successors) stack.emplace_back(next, 1);
        while (!stack.empty()) {
            auto [id, place] = stack.back();
            stack.pop_back();
            path.resize(place);
            path.push_back(id);
            if (isDrawNode(id)) {
                paths.push_back(path);
                continue;
            }
            for (NodeId next : nodes_[id].successors) stack.emplace_back(next, place + 1);
        }
    }
    std::ranges::sort(paths, {}, [](const std::vector<NodeId> &p) { return std::pair(p.front(), p.back()); });
    return paths;
}

// The words after `first` (already in the graph, its predecessors set) as new nodes: a word
// hangs on the one before it, a `[` opens a branch that its `]` closes, and the word after a
// `]` hangs on the word before the matching `[`. Returns the node a following word hangs on.
NodeId WordGraph::appendChain(std::span<const Word> words, NodeId first, uint32_t depth) {
    std::vector<NodeId> openers;
    NodeId current = kNoNode;
    for (size_t i = 0; i < words.size(); ++i) {
        NodeId id = i == 0 ? first : addNode(current);
        WordNode &node = nodes_[id];
        node.word = words[i];
        node.depth = depth;
        node.opener = kNoNode;
        if (node.word.symbol == ']') {
            if (openers.empty()) throw std::invalid_argument("a ']' without its '['");
            node.opener = openers.back();
            openers.pop_back();
        }
        place(id);
        if (node.word.symbol == '[') openers.push_back(id);
        current = node.opener != kNoNode ? predecessorOf(node.opener) : id;
    }
    return current;
}

NodeId WordGraph::addNode(NodeId attachTo) {
    NodeId id = NodeId(nodes_.size());
    nodes_.emplace_back().id = id;
    if (attachTo != kNoNode) link(attachTo, id);
    return id;
}

void WordGraph::link(NodeId from, NodeId to) {
    nodes_[from].successors.push_back(to);
    nodes_[to].predecessors.push_back(from);
}

// A node's turtle is its word applied to the turtle before it: its predecessor's, or for a
// `]` the one before its `[` (what a pop restores); a node with nothing before starts afresh.
void WordGraph::place(NodeId id) {
    WordNode &node = nodes_[id];
    NodeId before = predecessorOf(node.opener != kNoNode ? node.opener : id);
    node.turtle = moveTurtle(before == kNoNode ? Turtle{} : nodes_[before].turtle, node.word);
}

// Predecessors before successors, so each node is placed from an up-to-date one.
void WordGraph::placeSubtreesAgain(std::span<const NodeId> roots) {
    std::vector<NodeId> stack(roots.begin(), roots.end());
    while (!stack.empty()) {
        NodeId id = stack.back();
        stack.pop_back();
        place(id);
        stack.insert(stack.end(), nodes_[id].successors.begin(), nodes_[id].successors.end());
    }
}

NodeId WordGraph::predecessorOf(NodeId id) const {
    return nodes_[id].predecessors.empty() ? kNoNode : nodes_[id].predecessors.front();
}

}  // namespace veduta
