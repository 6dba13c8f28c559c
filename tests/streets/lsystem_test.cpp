#include "streets/lsystem.h"

#include <gtest/gtest.h>

#include "input_error.h"
#include "streets/fixed_draws.h"
#include "streets/street_rule_file.h"

namespace veduta {
namespace {

using test::FixedDraws;

StreetRuleSet rules(const std::string &text) { return parseStreetRules(text, "r.txt"); }

std::string rewriteTimes(const StreetRuleSet &set, int steps) {
    FixedDraws draws(0.5f);
    std::vector<std::string> warnings;
    std::vector<Word> words = set.initialWord;
    for (int i = 0; i < steps; ++i) words = rewrite(words, set, draws, uint32_t(i), warnings);
    EXPECT_TRUE(warnings.empty());
    return toString(words);
}

TEST(LSystemRewrite, StairSystem) {
    StreetRuleSet stairs = rules("w: A\np: A -> F+F-A\n");
    EXPECT_EQ(rewriteTimes(stairs, 1), "F+F-A");
    EXPECT_EQ(rewriteTimes(stairs, 5), "F+F-F+F-F+F-F+F-F+F-A");
}

TEST(LSystemRewrite, ContextSensitiveSystem) {
    StreetRuleSet signal = rules("w: baaa\np1: b < a -> b\np2: b -> a\n");
    EXPECT_EQ(rewriteTimes(signal, 1), "abaa");
    EXPECT_EQ(rewriteTimes(signal, 2), "aaba");
    EXPECT_EQ(rewriteTimes(signal, 3), "aaab");
}

TEST(LSystemMatching, HeadNeedsSymbolAndArity) {
    StreetRuleSet set = rules("o: A\np: S(a) -> F\n");
    const StreetRule &rule = set.rules[0];
    auto matches = [&](Word word) { return headMatches(rule, std::span(&word, 1), 0); };
    EXPECT_TRUE(matches({'S', {10}}));
    EXPECT_FALSE(matches({'X', {}}));
    EXPECT_FALSE(matches({'X', {10}}));
    EXPECT_FALSE(matches({'S', {}}));
    EXPECT_FALSE(matches({'S', {10, 2}}));
}

TEST(LSystemMatching, ContextMustBeAdjacent) {
    StreetRuleSet set = rules("o: A\np: b < a > c -> F\n");
    std::vector<Word> words = {{'b', {}}, {'a', {}}, {'c', {}}, {'a', {}}};
    EXPECT_TRUE(headMatches(set.rules[0], words, 1));
    EXPECT_FALSE(headMatches(set.rules[0], words, 3));  // nothing after it
}

TEST(LSystemSelection, DrawsPickByCumulativeProbability) {
    const float p[] = {0.15f, 0.5f, 0.35f};
    EXPECT_EQ(selectByProbability(p, 0.1f), 0u);
    EXPECT_EQ(selectByProbability(p, 0.3f), 1u);
    EXPECT_EQ(selectByProbability(p, 0.9f), 2u);
    EXPECT_EQ(selectByProbability(p, 0.66f), 2u);
    EXPECT_EQ(selectByProbability(p, 0.64f), 1u);
}

std::string expandWithDraw(const StreetRuleSet &set, float draw, std::vector<std::string> &warnings) {
    FixedDraws draws(draw);
    WordDraws wordDraws(draws, 0);
    std::vector<Word> word = set.initialWord;
    auto successor = expandWord(word, 0, set.rules, wordDraws, {}, warnings);
    return successor ? toString(*successor) : "no rule";
}

TEST(LSystemSelection, ExpandChoosesAmongMatchingRules) {
    StreetRuleSet set = rules("o: A\nr1: A -> F : 0.15\nr2: A -> f : 0.5\nr3: A -> + : 0.35\nx: B -> F\n");
    std::vector<std::string> warnings;
    EXPECT_EQ(expandWithDraw(set, 0.1f, warnings), "F");
    EXPECT_EQ(expandWithDraw(set, 0.3f, warnings), "f");
    EXPECT_EQ(expandWithDraw(set, 0.9f, warnings), "+");
    EXPECT_TRUE(warnings.empty());
}

TEST(LSystemSelection, ProbabilitiesNotSummingToOneAreRescaledWithAWarning) {
    // 0.3 and 0.5 rescale to 0.375 and 0.625: a draw of 0.35 picks r1 (it would pick r2 unscaled).
    StreetRuleSet set = rules("o: A\nr1: A -> F : 0.3\nr2: A -> f : 0.5\n");
    std::vector<std::string> warnings;
    EXPECT_EQ(expandWithDraw(set, 0.35f, warnings), "F");
    EXPECT_EQ(expandWithDraw(set, 0.9f, warnings), "f");
    ASSERT_EQ(warnings.size(), 1u);  // once, not per word
    EXPECT_EQ(warnings[0], "r.txt:2:1: rules r1, r2 match a word A with probabilities summing to 0.8, not 1: rescaled");
}

TEST(LSystemEvaluation, WorkedExampleOfTheThesis) {
    // L2430–2463: S(10), random mocked to 0.312, the query leaving res = NORMAL.
    StreetRuleSet set =
        rules("o: S(10)\np: S(len) > ?I(a,len,res) : res != NN {a=0; c=3;} -> +(0.5*c*random(0,1))F(len*1.5)\n");
    std::vector<float> queried;
    StreetQuery query = [&](char kind, std::span<float> inOut) {
        EXPECT_EQ(kind, 'I');
        queried.assign(inOut.begin(), inOut.end());
        return QueryResult::Normal;
    };
    FixedDraws draws(0.312f);
    WordDraws wordDraws(draws, 0);
    std::vector<std::string> warnings;
    auto successor = expandWord(set.initialWord, 0, set.rules, wordDraws, query, warnings);
    ASSERT_TRUE(successor);
    EXPECT_EQ(toString(*successor), "+(0.468)F(15)");
    EXPECT_EQ(queried, (std::vector<float>{0, 10}));  // a = 0 ran before the query
}

TEST(LSystemEvaluation, QueryResultDecidesBetweenListing42Rules) {
    StreetRuleSet set = parseStreetRules(R"(#define ProbChangeStreetAngle 0.20
#define DevStreetAngle 10
#define ProbChangeStreetLength 0.20

o: S(10)
p1: S(len) > ?I(a,len,insertion) : insertion == NORMAL {a = ProbChangeStreetAngle ? U[-DevStreetAngle,DevStreetAngle] : 0.0; len = ProbChangeStreetLength ? U[0.5*len,1.5*len] : len;} -> &(a)F(len)[+(80)P][&(90)S(len)][&(-90)S(len)]&(a)S(len)
p2: S(len) > ?I(a,len,insertion) : insertion == NN || insertion == INTSCT || insertion == FWD_INTSCT -> &(a)F(len)
)",
                                         "manhattan.txt");
    std::vector<std::string> warnings;
    auto expand = [&](QueryResult answer, float draw) {
        FixedDraws draws(draw);
        WordDraws wordDraws(draws, 0);
        StreetQuery query = [&](char, std::span<float> inOut) {
            if (answer == QueryResult::NearestNeighbour) inOut[1] = 7;  // shortened to the neighbour
            return answer;
        };
        return toString(*expandWord(set.initialWord, 0, set.rules, wordDraws, query, warnings));
    };
    // A draw of 0.5 is above both probabilities 0.2: a = 0.0 and len stays.
    EXPECT_EQ(expand(QueryResult::Normal, 0.5f), "&(0)F(10)[+(80)P][&(90)S(10)][&(-90)S(10)]&(0)S(10)");
    // A draw of 0.1 takes U[…] each time: a = -10 + 20 * 0.1, len = 5 + 10 * 0.1.
    EXPECT_EQ(expand(QueryResult::Normal, 0.1f), "&(-8)F(6)[+(80)P][&(90)S(6)][&(-90)S(6)]&(-8)S(6)");
    EXPECT_EQ(expand(QueryResult::NearestNeighbour, 0.5f), "&(0)F(7)");
    EXPECT_TRUE(warnings.empty());
}

TEST(LSystemEvaluation, QueryNeedsTheCallersAnswer) {
    StreetRuleSet set = rules("o: S(10)\np: S(len) > ?E(a,len,res) -> F\n");
    FixedDraws draws(0.5f);
    std::vector<std::string> warnings;
    EXPECT_EQ(test::inputErrorOf([&] { rewrite(set.initialWord, set, draws, 0, warnings); }),
              "r.txt:2:14: ?E needs the street graph, which a plain rewrite has not");
}

TEST(LSystemDeterminism, SeededDrawsDependOnSeedWordAndIndex) {
    SeededDraws a(7), b(7), other(8);
    EXPECT_EQ(a.uniform(3, 0), b.uniform(3, 0));
    EXPECT_NE(a.uniform(3, 0), a.uniform(4, 0));
    EXPECT_NE(a.uniform(3, 0), a.uniform(3, 1));
    EXPECT_NE(a.uniform(3, 0), other.uniform(3, 0));
    for (uint32_t i = 0; i < 100; ++i) {
        float u = a.uniform(i, i);
        EXPECT_TRUE(u >= 0 && u < 1);
    }
}

TEST(LSystemDeterminism, SameSeedSameRewrite) {
    StreetRuleSet set = rules("o: A(1)A(1)\np: A(x) -> F(U[0,10])A(x)\n");
    auto grow = [&](uint32_t seed) {
        SeededDraws draws(seed);
        std::vector<std::string> warnings;
        std::vector<Word> words = set.initialWord;
        for (uint32_t i = 0; i < 3; ++i) words = rewrite(words, set, draws, i, warnings);
        return words;
    };
    std::vector<Word> first = grow(1);
    EXPECT_EQ(toString(first), toString(grow(1)));
    EXPECT_NE(toString(first), toString(grow(2)));
    // The two words of the initial word are different identities: their draws differ.
    EXPECT_NE(first[0].parameters, first[first.size() / 2].parameters);
}

}  // namespace
}  // namespace veduta
