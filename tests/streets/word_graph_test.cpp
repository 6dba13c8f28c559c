#include "streets/word_graph.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace veduta {
namespace {

// Words as a rule's successor gives them: `F(10)` is {'F', {10}}.
std::vector<Word> words(std::initializer_list<Word> list) { return list; }

Vec3f endOf(std::initializer_list<Word> list) {
    Turtle turtle;
    for (const Word &word : list) turtle = moveTurtle(turtle, word);
    return turtle.position;
}

void expectNear(const Vec3f &actual, const Vec3f &expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-4f);
    EXPECT_NEAR(actual.y, expected.y, 1e-4f);
    EXPECT_NEAR(actual.z, expected.z, 1e-4f);
}

TEST(WordGraphTurtle, StartsAtTheOriginHeadingXWithZUp) {
    expectNear(endOf({{'F', {10}}}), {10, 0, 0});
    expectNear(endOf({{'f', {10}}}), {10, 0, 0});
}

TEST(WordGraphTurtle, AmpersandTurnsInTheGroundPlanePositiveRight) {
    expectNear(endOf({{'&', {90}}, {'F', {10}}}), {0, -10, 0});
    expectNear(endOf({{'&', {-90}}, {'F', {10}}}), {0, 10, 0});
    expectNear(endOf({{'&', {}}, {'F', {10}}}), {0, -10, 0});  // 90° without a parameter
}

TEST(WordGraphTurtle, PlusPitchesUpMinusDown) {
    expectNear(endOf({{'+', {90}}, {'F', {10}}}), {0, 0, 10});
    expectNear(endOf({{'-', {90}}, {'F', {10}}}), {0, 0, -10});
}

TEST(WordGraphTurtle, RollsAndTurnAround) {
    // Rolled right by 90°, the left is up: a turn to the right then descends.
    expectNear(endOf({{'/', {90}}, {'&', {90}}, {'F', {10}}}), {0, 0, -10});
    expectNear(endOf({{'\\', {90}}, {'&', {90}}, {'F', {10}}}), {0, 0, 10});
    expectNear(endOf({{'|', {}}, {'F', {10}}}), {-10, 0, 0});
}

TEST(WordGraphTurtle, OtherSymbolsNeitherMoveNorTurn) {
    expectNear(endOf({{'^', {30}}, {'!', {}}, {'S', {10}}, {'P', {}}, {'F', {10}}}), {10, 0, 0});
}

TEST(WordGraphStructure, BracketsBranchIntoATree) {
    WordGraph graph(words({{'A', {}}, {'[', {}}, {'B', {}}, {']', {}}, {'C', {}}}));
    ASSERT_EQ(graph.size(), 5u);
    EXPECT_EQ(graph.node(0).successors, (std::vector<NodeId>{1, 4}));  // the `[` and the word after `]`
    EXPECT_EQ(graph.node(1).successors, (std::vector<NodeId>{2}));
    EXPECT_EQ(graph.node(2).successors, (std::vector<NodeId>{3}));
    EXPECT_TRUE(graph.node(3).successors.empty());
    EXPECT_EQ(graph.node(4).predecessors, (std::vector<NodeId>{0}));
    EXPECT_EQ(graph.node(3).opener, 1u);
}

TEST(WordGraphExpand, FirstWordKeepsTheIdAndTheFollowersMove) {
    WordGraph graph(words({{'A', {}}, {'[', {}}, {'B', {}}, {']', {}}, {'C', {}}}));
    graph.expand(0, words({{'F', {10}}, {'G', {}}}));
    ASSERT_EQ(graph.size(), 6u);
    EXPECT_EQ(graph.node(0).word.symbol, 'F');
    EXPECT_EQ(graph.node(5).word.symbol, 'G');
    EXPECT_EQ(graph.node(0).depth, 1u);
    EXPECT_EQ(graph.node(5).depth, 1u);
    EXPECT_EQ(graph.node(4).depth, 0u);
    EXPECT_EQ(graph.node(0).successors, (std::vector<NodeId>{5}));
    EXPECT_EQ(graph.node(5).successors, (std::vector<NodeId>{1, 4}));
    EXPECT_EQ(graph.node(1).predecessors, (std::vector<NodeId>{5}));
    for (NodeId id : {1u, 2u, 3u, 4u, 5u}) expectNear(graph.node(id).turtle.position, {10, 0, 0});
}

TEST(WordGraphExpand, ABranchClosesBackToTheTurtleBeforeIt) {
    WordGraph graph(words({{'F', {10}}, {'[', {}}, {'B', {}}, {']', {}}, {'F', {5}}}));
    graph.expand(2, words({{'&', {90}}, {'F', {5}}}));
    ASSERT_EQ(graph.size(), 6u);
    EXPECT_EQ(graph.node(5).successors, (std::vector<NodeId>{3}));  // the `]` ends the grown branch
    expectNear(graph.node(5).turtle.position, {10, -5, 0});
    expectNear(graph.node(3).turtle.position, {10, 0, 0});
    expectNear(graph.node(3).turtle.heading, {1, 0, 0});
    expectNear(graph.node(4).turtle.position, {15, 0, 0});
}

TEST(WordGraphExpand, EmptySuccessorIsRefused) {
    WordGraph graph(words({{'A', {}}}));
    EXPECT_THROW(graph.expand(0, {}), std::invalid_argument);
}

TEST(WordGraphDrawPaths, JoinDrawNodesThroughTheWordsBetween) {
    WordGraph graph(
        words({{'A', {}}, {'F', {10}}, {'[', {}}, {'&', {90}}, {'F', {10}}, {']', {}}, {'S', {}}, {'F', {10}}}));
    EXPECT_TRUE(graph.isDrawNode(0));  // the root
    EXPECT_FALSE(graph.isDrawNode(6));
    std::vector<std::vector<NodeId>> expected = {{0, 1}, {1, 2, 3, 4}, {1, 6, 7}};
    EXPECT_EQ(graph.drawPaths(), expected);  // the branch's `]` ends no edge
}

}  // namespace
}  // namespace veduta
