#include "streets/expression.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/check.h"
#include "streets/query_result.h"

namespace veduta {

void Bindings::set(std::string_view name, float value) {
    for (auto &[known, v] : values_) {
        if (known == name) {
            v = value;
            return;
        }
    }
    values_.emplace_back(std::string(name), value);
}

const float *Bindings::find(std::string_view name) const {
    for (const auto &[known, value] : values_) {
        if (known == name) return &value;
    }
    return nullptr;
}

namespace {

using Op = Expression::Op;

// The binary operators of one precedence level, longest spelling first.
struct BinaryOp {
    std::string_view token;
    Op op;
};
constexpr BinaryOp kOrOps[] = {{"||", Op::Or}};
constexpr BinaryOp kAndOps[] = {{"&&", Op::And}};
constexpr BinaryOp kEqualityOps[] = {{"==", Op::Equal}, {"!=", Op::NotEqual}};
constexpr BinaryOp kRelationalOps[] = {
    {"<=", Op::LessEqual}, {">=", Op::GreaterEqual}, {"<", Op::Less}, {">", Op::Greater}};
constexpr BinaryOp kAdditiveOps[] = {{"+", Op::Add}, {"-", Op::Subtract}};
constexpr BinaryOp kMultiplicativeOps[] = {{"*", Op::Multiply}, {"/", Op::Divide}};

}  // namespace

// Recursive descent, one function per precedence level (C's order).
class ExpressionParser {
  public:
    explicit ExpressionParser(TextCursor &cursor) : cursor_(cursor) {}

    Expression parse() {
        cursor_.skipSpace();
        expression_.loc_ = cursor_.loc();
        expression_.root_ = parseLevel(0);
        return std::move(expression_);
    }

  private:
    static constexpr std::span<const BinaryOp> kLevels[] = {kOrOps,         kAndOps,      kEqualityOps,
                                                            kRelationalOps, kAdditiveOps, kMultiplicativeOps};

    // Left-associative chains of the operators of `level`, then unary expressions.
    int parseLevel(size_t level) {
        if (level == std::size(kLevels)) return parseUnary();
        int left = parseLevel(level + 1);
        while (const BinaryOp *op = nextOperator(kLevels[level])) {
            FileLoc at = cursor_.loc();
            cursor_.advance(op->token.size());
            left = addNode(op->op, at, left, parseLevel(level + 1));
        }
        return left;
    }

    const BinaryOp *nextOperator(std::span<const BinaryOp> ops) {
        cursor_.skipSpace();
        // `->` ends a rule's condition; it is no minus.
        if (cursor_.lookingAt("->")) return nullptr;
        for (const BinaryOp &op : ops) {
            if (cursor_.lookingAt(op.token)) return &op;
        }
        return nullptr;
    }

    int parseUnary() {
        Nesting nesting(*this);
        cursor_.skipSpace();
        FileLoc at = cursor_.loc();
        if (cursor_.peek() == '-' && cursor_.peek(1) != '>') {
            cursor_.advance();
            return addNode(Op::Negate, at, parseUnary());
        }
        return parsePrimary();
    }

    int parsePrimary() {
        cursor_.skipSpace();
        FileLoc at = cursor_.loc();
        char c = cursor_.peek();
        if (isDigit(c) || c == '.') return parseNumber();
        if (c == '(') {
            cursor_.advance();
            int inner = parseLevel(0);
            cursor_.expect(")", "to close the parenthesis");
            return inner;
        }
        if (!isNameStart(c)) {
            cursor_.fail("expected a number, a name or '(', found " + cursor_.describeNext());
        }
        std::string name;
        while (isNameChar(cursor_.peek())) {
            name += cursor_.peek();
            cursor_.advance();
        }
        if (name == "U" && cursor_.consume("[")) return parseArguments(Op::Uniform, at, "]");
        if (name == "random" && cursor_.consume("(")) return parseArguments(Op::Random, at, ")");
        if (name == "max" && cursor_.consume("(")) return parseArguments(Op::Max, at, ")");
        int node = addNode(Op::Name, at);
        expression_.nodes_[node].name = std::move(name);
        return node;
    }

    // Two arguments and the closing bracket: U[a,b], random(a,b), max(a,b).
    int parseArguments(Op op, const FileLoc &at, std::string_view close) {
        int first = parseLevel(0);
        cursor_.expect(",", "between the two arguments");
        int second = parseLevel(0);
        cursor_.expect(close, "after the two arguments");
        return addNode(op, at, first, second);
    }

    // Digits with an optional fraction: 10, 0.5, .5, 10. (no exponent, no sign: that is minus).
    int parseNumber() {
        FileLoc at = cursor_.loc();
        std::string text;
        while (isDigit(cursor_.peek()) || cursor_.peek() == '.') {
            text += cursor_.peek();
            cursor_.advance();
        }
        float value = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc::result_out_of_range) throw InputError(at, "number '" + text + "' is out of range");
        if (error != std::errc() || end != text.data() + text.size()) {
            throw InputError(at, "malformed number '" + text + "'");
        }
        int node = addNode(Op::Number, at);
        expression_.nodes_[node].value = value;
        return node;
    }

    int addNode(Op op, const FileLoc &at, int left = -1, int right = -1) {
        Expression::Node node;
        node.op = op;
        node.left = left;
        node.right = right;
        node.line = at.line;
        node.column = at.column;
        for (int child : {left, right}) {
            if (child >= 0) node.depth = std::max(node.depth, expression_.nodes_[child].depth + 1);
        }
        if (node.depth > kMaxExpressionDepth) {
            throw InputError(at, "expression nested deeper than " + std::to_string(kMaxExpressionDepth) + " levels");
        }
        expression_.nodes_.push_back(std::move(node));
        return int(expression_.nodes_.size()) - 1;
    }

    // Bounds the parser's own recursion (parentheses, unary minus) as addNode bounds the tree.
    struct Nesting {
        explicit Nesting(ExpressionParser &parser) : parser_(parser) {
            if (++parser_.nesting_ > kMaxExpressionDepth) {
                parser_.cursor_.fail("expression nested deeper than " + std::to_string(kMaxExpressionDepth) +
                                     " levels");
            }
        }
        ~Nesting() { --parser_.nesting_; }
        ExpressionParser &parser_;
    };

    TextCursor &cursor_;
    Expression expression_;
    int nesting_ = 0;
};

Expression Expression::parse(TextCursor &cursor) { return ExpressionParser(cursor).parse(); }

void Expression::resolveNames(const NameScope &scope) {
    for (Node &node : nodes_) {
        if (node.op != Op::Name) continue;
        if (std::ranges::find(scope.variables, node.name) != scope.variables.end()) {
            node.op = Op::Variable;
        } else if (auto code = queryResultNamed(node.name)) {
            node.op = Op::Number;
            node.value = float(*code);
        } else if (auto define = std::ranges::find(scope.defines, node.name, &Define::name);
                   define != scope.defines.end()) {
            node.op = Op::Number;
            node.value = define->value;
        } else {
            throw InputError(nodeLoc(node), "unknown name '" + node.name + "'");
        }
    }
}

bool Expression::isConstant() const {
    return std::ranges::all_of(nodes_, [](const Node &node) {
        return node.op != Op::Variable && node.op != Op::Name && node.op != Op::Uniform && node.op != Op::Random;
    });
}

float Expression::constantValue() const {
    VEDUTA_CHECK(isConstant(), "constantValue of an expression with variables or draws");
    return evaluateNode(root_, nullptr, nullptr);
}

float Expression::evaluate(const Bindings &bindings, WordDraws &draws) const {
    return evaluateNode(root_, &bindings, &draws);
}

float Expression::evaluateNode(int index, const Bindings *bindings, WordDraws *draws) const {
    const Node &node = nodes_[index];
    auto operand = [&](int child) { return evaluateNode(child, bindings, draws); };
    auto finite = [&](float value) {
        if (!std::isfinite(value)) throw InputError(nodeLoc(node), "the value is not a finite number");
        return value;
    };
    switch (node.op) {
    case Op::Number: return node.value;
    case Op::Variable: {
        const float *value = bindings->find(node.name);
        if (!value) throw InputError(nodeLoc(node), "'" + node.name + "' has no value yet");
        return *value;
    }
    case Op::Name: VEDUTA_UNREACHABLE("an unresolved name '" + node.name + "' is evaluated");
    case Op::Negate: return -operand(node.left);
    case Op::Add: return finite(operand(node.left) + operand(node.right));
    case Op::Subtract: return finite(operand(node.left) - operand(node.right));
    case Op::Multiply: return finite(operand(node.left) * operand(node.right));
    case Op::Divide: {
        float numerator = operand(node.left), denominator = operand(node.right);
        if (denominator == 0) throw InputError(nodeLoc(node), "division by zero");
        return finite(numerator / denominator);
    }
    case Op::Less: return float(operand(node.left) < operand(node.right));
    case Op::LessEqual: return float(operand(node.left) <= operand(node.right));
    case Op::Greater: return float(operand(node.left) > operand(node.right));
    case Op::GreaterEqual: return float(operand(node.left) >= operand(node.right));
    case Op::Equal: return float(operand(node.left) == operand(node.right));
    case Op::NotEqual: return float(operand(node.left) != operand(node.right));
    // Short-circuit as in C: the right side is not evaluated (and draws nothing) when the
    // left decides.
    case Op::And: return float(operand(node.left) != 0 && operand(node.right) != 0);
    case Op::Or: return float(operand(node.left) != 0 || operand(node.right) != 0);
    case Op::Uniform:
    case Op::Random: {
        float low = operand(node.left), high = operand(node.right);
        return finite(low + (high - low) * draws->next());
    }
    case Op::Max: return std::max(operand(node.left), operand(node.right));
    }
    VEDUTA_UNREACHABLE("unknown expression operator");
}

Expression parseExpressionText(std::string_view text, const std::string &file, const NameScope &scope) {
    TextCursor cursor(text, file, 1);
    Expression expression = Expression::parse(cursor);
    if (!cursor.atEnd()) cursor.fail("unexpected " + cursor.describeNext() + " after the expression");
    expression.resolveNames(scope);
    return expression;
}

}  // namespace veduta
