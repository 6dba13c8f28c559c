// The arithmetic of street rules (Goitowski 2010, §4.2.2): numbers, names, + - * / with
// precedence and parentheses, unary minus, U[a,b], random(a,b), max(a,b), the comparisons
// > >= < <= == != and the connectives && and || (C's precedence: && binds tighter than ||).
// An expression is parsed once into a tree of nodes and evaluated against the values of a
// rule's variables and the word's random draws. docs/street-rules.md is the reference.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"
#include "streets/random_draws.h"
#include "streets/text_cursor.h"

namespace veduta {

// Deeper trees are refused: the evaluator recurses, and a fuzzer's input must not exhaust
// the stack. A street rule's expressions are a few levels deep.
inline constexpr int kMaxExpressionDepth = 100;

// `#define Name value`: a constant of the rule file.
struct Define {
    std::string name;
    float value = 0;
};

// What names an expression may use: the file's defines, the query result codes (always) and
// the rule's variables (its parameters, query parameters and assignment targets).
struct NameScope {
    std::span<const Define> defines;
    std::span<const std::string> variables;
};

// The values of a rule's variables while one word is expanded.
class Bindings {
  public:
    void set(std::string_view name, float value);
    const float *find(std::string_view name) const;

  private:
    std::vector<std::pair<std::string, float>> values_;
};

class Expression {
  public:
    enum class Op {
        Number,
        Variable,
        Name,  // Name: not yet resolved to a number or a variable
        Negate,
        Add,
        Subtract,
        Multiply,
        Divide,
        Less,
        LessEqual,
        Greater,
        GreaterEqual,
        Equal,
        NotEqual,
        And,
        Or,
        Uniform,
        Random,
        Max,
    };

    // Parses as much of the cursor's text as forms an expression and stops before the first
    // character that cannot continue it (`->`, `{`, `;`, `?`, `:`, `,` …). Names stay unresolved.
    static Expression parse(TextCursor &cursor);

    // Turns every name into a define's value, a query result code or a variable of `scope`;
    // throws InputError at the first name that is none of them.
    void resolveNames(const NameScope &scope);

    // The value; a comparison or connective is 1 (true) or 0 (false). Throws InputError at the
    // node that divides by zero, reads a variable without a value or leaves the finite floats.
    float evaluate(const Bindings &bindings, WordDraws &draws) const;
    bool isTrue(const Bindings &bindings, WordDraws &draws) const { return evaluate(bindings, draws) != 0; }

    // Neither variables nor draws: a value known when the file is read.
    bool isConstant() const;
    float constantValue() const;

    const FileLoc &loc() const { return loc_; }

  private:
    friend class ExpressionParser;
    struct Node {
        Op op = Op::Number;
        float value = 0;   // Number
        std::string name;  // Variable, Name
        int left = -1, right = -1;
        int depth = 1;  // of the subtree
        int line = 0, column = 0;
    };
    float evaluateNode(int index, const Bindings *bindings, WordDraws *draws) const;
    FileLoc nodeLoc(const Node &node) const { return {loc_.file, node.line, node.column}; }

    std::vector<Node> nodes_;
    int root_ = -1;
    FileLoc loc_;
};

// The whole of `text` as one expression, resolved in `scope` (messages name `file`, line 1).
Expression parseExpressionText(std::string_view text, const std::string &file, const NameScope &scope);

}  // namespace veduta
