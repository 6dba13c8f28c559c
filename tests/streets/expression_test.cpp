#include "streets/expression.h"

#include <gtest/gtest.h>

#include <deque>

#include "input_error.h"
#include "streets/query_result.h"

namespace veduta {
namespace {

// Draws from a list, in order; the test fails if more are asked for.
class ListedDraws final : public RandomDraws {
  public:
    explicit ListedDraws(std::deque<float> values) : values_(std::move(values)) {}
    float uniform(uint32_t, uint32_t) override {
        EXPECT_FALSE(values_.empty()) << "more draws than listed";
        if (values_.empty()) return 0;
        float value = values_.front();
        values_.pop_front();
        return value;
    }

  private:
    std::deque<float> values_;
};

const std::vector<Define> kDefines = {{"Dev", 10}, {"Half", 0.5f}};

float evaluate(std::string_view text, const Bindings &bindings = {}, std::deque<float> draws = {}) {
    std::vector<std::string> variables = {"a", "b", "len", "insertion", "res", "c"};
    Expression expression = parseExpressionText(text, "rules.txt", {kDefines, variables});
    ListedDraws listed(std::move(draws));
    WordDraws wordDraws(listed, 1);
    return expression.evaluate(bindings, wordDraws);
}

Bindings bind(std::initializer_list<std::pair<const char *, float>> values) {
    Bindings bindings;
    for (auto [name, value] : values) bindings.set(name, value);
    return bindings;
}

TEST(StreetRuleExpression, ArithmeticHasPrecedenceAndParentheses) {
    EXPECT_FLOAT_EQ(evaluate("1 + 2 * 3"), 7);
    EXPECT_FLOAT_EQ(evaluate("(1 + 2) * 3"), 9);
    EXPECT_FLOAT_EQ(evaluate("10 - 4 - 3"), 3);  // left-associative
    EXPECT_FLOAT_EQ(evaluate("12 / 3 / 2"), 2);
    EXPECT_FLOAT_EQ(evaluate("-Dev + -(-2)"), -8);
    EXPECT_FLOAT_EQ(evaluate("Half*len", bind({{"len", 10}})), 5);
    EXPECT_FLOAT_EQ(evaluate("max(3, len)", bind({{"len", 10}})), 10);
}

TEST(StreetRuleExpression, ConditionsOfTheThesis) {
    // Tab. 4.2.1: a>5 && a<20 with a = 10.
    EXPECT_EQ(evaluate("a>5 && a<20", bind({{"a", 10}})), 1);
    EXPECT_EQ(evaluate("a>5 && a<20", bind({{"a", 20}})), 0);
    // Listing 4.2's p2: NN is true, NORMAL is not.
    const char *p2 = "insertion == NN || insertion == INTSCT || insertion == FWD_INTSCT";
    EXPECT_EQ(evaluate(p2, bind({{"insertion", float(QueryResult::NearestNeighbour)}})), 1);
    EXPECT_EQ(evaluate(p2, bind({{"insertion", float(QueryResult::Normal)}})), 0);
    EXPECT_EQ(evaluate("res != NN", bind({{"res", float(QueryResult::Normal)}})), 1);
    EXPECT_EQ(evaluate("a >= 10 && a <= 10 && a == 10", bind({{"a", 10}})), 1);
}

TEST(StreetRuleExpression, AndBindsTighterThanOr) {
    // As (1 || 0) && 0 this would be 0; as in C it is 1 || (0 && 0).
    EXPECT_EQ(evaluate("1 || 0 && 0"), 1);
    EXPECT_EQ(evaluate("(1 || 0) && 0"), 0);
}

TEST(StreetRuleExpression, DrawsComeFromTheSource) {
    EXPECT_FLOAT_EQ(evaluate("U[-Dev, Dev]", {}, {0.75f}), 5);
    EXPECT_FLOAT_EQ(evaluate("0.5*c*random(0,1)", bind({{"c", 3}}), {0.312f}), 0.468f);
}

TEST(StreetRuleExpression, ErrorsNameTheirPlace) {
    using test::inputErrorOf;
    EXPECT_EQ(inputErrorOf([] { evaluate("a + nope"); }), "rules.txt:1:5: unknown name 'nope'");
    EXPECT_EQ(inputErrorOf([] { evaluate("1 / (a - a)", bind({{"a", 2}})); }), "rules.txt:1:3: division by zero");
    EXPECT_EQ(inputErrorOf([] { evaluate("len * 2"); }), "rules.txt:1:1: 'len' has no value yet");
    EXPECT_EQ(inputErrorOf([] { evaluate("(1 + 2"); }),
              "rules.txt:1:7: expected ')' to close the parenthesis, found the end of the line");
    EXPECT_EQ(inputErrorOf([] { evaluate("1 + * 2"); }), "rules.txt:1:5: expected a number, a name or '(', found '*'");
    EXPECT_EQ(inputErrorOf([] { evaluate("U[1 2]"); }),
              "rules.txt:1:5: expected ',' between the two arguments, found '2'");
    EXPECT_EQ(inputErrorOf([] { evaluate("1.2.3"); }), "rules.txt:1:1: malformed number '1.2.3'");
    EXPECT_EQ(inputErrorOf([] { evaluate("2 3"); }), "rules.txt:1:3: unexpected '3' after the expression");
}

TEST(StreetRuleExpression, DepthIsLimited) {
    std::string nested = std::string(200, '(') + "1" + std::string(200, ')');
    EXPECT_NE(test::inputErrorOf([&] { evaluate(nested); }).find("nested deeper than 100"), std::string::npos);
    std::string chain = "1";
    for (int i = 0; i < 200; ++i) chain += "+1";
    EXPECT_NE(test::inputErrorOf([&] { evaluate(chain); }).find("nested deeper than 100"), std::string::npos);
    std::string shallow = "1";
    for (int i = 0; i < 50; ++i) shallow += "+1";
    EXPECT_FLOAT_EQ(evaluate(shallow), 51);
}

}  // namespace
}  // namespace veduta
