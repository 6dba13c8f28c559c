#include "streets/street_rule_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <utility>

#include "input_error.h"
#include "streets/listing_4_2.h"

namespace veduta {
namespace {

using test::inputErrorOf;
using test::kListing42;

std::string errorOf(const std::string &text) {
    return inputErrorOf([&] { parseStreetRules(text, "r.txt"); });
}

TEST(StreetRuleFile, ReadsListing42Verbatim) {
    StreetRuleSet set = parseStreetRules(kListing42, "manhattan.txt");
    ASSERT_EQ(set.defines.size(), 3u);
    EXPECT_EQ(set.defines[1].name, "DevStreetAngle");
    EXPECT_FLOAT_EQ(set.defines[0].value, 0.2f);
    EXPECT_FLOAT_EQ(set.defines[1].value, 10);
    EXPECT_EQ(set.initialName, "o");
    EXPECT_EQ(toString(set.initialWord), "S(10)");
    ASSERT_EQ(set.rules.size(), 2u);
    const StreetRule &p1 = set.rules[0];
    EXPECT_EQ(p1.label, "p1");
    EXPECT_EQ(p1.head.symbol, 'S');
    EXPECT_EQ(p1.head.parameters, std::vector<std::string>{"len"});
    ASSERT_TRUE(p1.query);
    EXPECT_EQ(p1.query->kind, 'I');
    EXPECT_EQ(p1.query->parameters, (std::vector<std::string>{"a", "len", "insertion"}));
    ASSERT_EQ(p1.assignments.size(), 2u);
    EXPECT_EQ(p1.assignments[0].variable, "a");
    EXPECT_TRUE(p1.assignments[0].probability && p1.assignments[0].valueFalse);
    EXPECT_FLOAT_EQ(p1.assignments[0].probability->constantValue(), 0.2f);
    EXPECT_EQ(p1.successor.size(), 16u);  // & F [ + P ] [ & S ] [ & S ] & S
    EXPECT_FLOAT_EQ(p1.probability, 1);
    EXPECT_EQ(set.rules[1].successor.size(), 2u);
    EXPECT_TRUE(set.rules[1].condition);
    EXPECT_TRUE(set.rules[1].assignments.empty());
    EXPECT_EQ(p1.loc.toString(), "manhattan.txt:6:1");
}

TEST(StreetRuleFile, ReadsMinimalContextAndProbabilityRules) {
    StreetRuleSet set = parseStreetRules(
        "// stochastic stairs\n\nw: A\np3: A -> F(10)\nq: b < a -> b // comment\nr: A > B C(x) : x > 1 -> F+FF-A : "
        "0.3\n",
        "r.txt");
    ASSERT_EQ(set.rules.size(), 3u);
    EXPECT_TRUE(set.rules[0].leftContext.empty() && !set.rules[0].condition && !set.rules[0].query);
    ASSERT_EQ(set.rules[1].leftContext.size(), 1u);
    EXPECT_EQ(set.rules[1].leftContext[0].symbol, 'b');
    EXPECT_EQ(set.rules[2].rightContext.size(), 2u);
    EXPECT_FLOAT_EQ(set.rules[2].probability, 0.3f);
    EXPECT_EQ(set.rules[2].successor.size(), 6u);
}

TEST(StreetRuleFile, RefusesWithPlace) {
    // Each text, and the message it must give.
    const std::pair<const char *, const char *> refused[] = {
        {"o: A\np1: A -> F\np1: A -> f\n", "r.txt:3:1: label 'p1' is already used on line 2"},
        {"o: A\np1: A(x) : y > 2 -> F\n", "r.txt:2:12: unknown name 'y'"},
        {"o: A\np1: S(len) > ?I(a,len) -> F\n", "r.txt:2:15: ?I takes 3 parameters (angle, length, result), not 2"},
        {"o: A\np1: A = F\n", "r.txt:2:7: expected '->' between the rule's head and its successor, found '='"},
        {"o: A\np1: A {a=1;}\n",
         "r.txt:2:13: expected '->' between the rule's head and its successor, found the end of the line"},
        {"o: A\np1: A -> F(1]\n", "r.txt:2:13: expected ')' after the parameters, found ']'"},
        {"o: A\np1: A -> F[+F\n", "r.txt:2:11: '[' without its ']'"},
        {"o: A\np1: A -> F]\n", "r.txt:2:11: ']' without its '['"},
        {"o: A\np1: A -> F{\n", "r.txt:2:11: '{' is no symbol of a word"},
        {"o: A\np1: A -> F : 1.5\n", "r.txt:2:14: a rule's probability must lie in [0, 1], not 1.5"},
        {"o: A\np1: A -> F : U[0,1]\n",
         "r.txt:2:14: a rule's probability must be a constant (numbers and defines), not a random draw"},
        {"o: A\np1: A B -> F\n",
         "r.txt:2:9: a rule's head is one word, not 2 (a context goes before '<' or after '>')"},
        {"o: A\np1: A > ?Q(a,b,c) -> F\n", "r.txt:2:10: unknown query 'Q' after '?' (there are ?I and ?E)"},
        {"o: A\np1: A(x,x) -> F\n", "r.txt:2:5: parameter 'x' is bound twice in the rule's head and context"},
        {"p1: A -> F\n", "r.txt:1:1: a rule before the initial word ('name: word')"},
        {"o: A\n#define X 1\n", "r.txt:2:8: a #define after the initial word (line 1): defines come first"},
        {"#define NN 3\no: A\n", "r.txt:1:9: 'NN' is a query result code and cannot be defined"},
        {"o: S(len)\n", "r.txt:1:6: unknown name 'len'"},
        {"#define X 1\n", "r.txt: no initial word (a line 'name: word', e.g. 'o: S(10)')"},
    };
    for (const auto &[text, message] : refused) EXPECT_EQ(errorOf(text), message) << text;
}

TEST(StreetRuleFile, ReadsAFileAndNamesIt) {
    std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "street_rules_test.txt";
    std::ofstream(file) << "o: A\np: A -> F(\n";
    EXPECT_EQ(inputErrorOf([&] { readStreetRuleFile(file); }),
              file.string() + ":2:11: expected a number, a name or '(', found the end of the line");
    std::ofstream(file) << kListing42;
    EXPECT_EQ(readStreetRuleFile(file).rules.size(), 2u);
    std::filesystem::remove(file);
}

TEST(StreetRuleFile, LimitsAreMessages) {
    std::string many = "o: A\np: A -> ";
    for (size_t i = 0; i <= kMaxWordsPerRule; ++i) many += 'F';
    EXPECT_NE(errorOf(many).find("more than 10000 words"), std::string::npos);
    std::string deep = "o: A\np: A -> F(" + std::string(300, '(') + "1" + std::string(300, ')') + ")";
    EXPECT_NE(errorOf(deep).find("nested deeper than 100 levels"), std::string::npos);
}

}  // namespace
}  // namespace veduta
