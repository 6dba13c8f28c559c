#include "streets/street_rule_file.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/input_file.h"
#include "streets/query_result.h"

namespace veduta {

namespace {

bool isBracket(char c) { return c == '[' || c == ']'; }

// The symbols a word may have: a letter or a turtle command (Tab. 2.3.2–2.3.4).
bool isSymbol(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
        std::string_view("+-&^/\\|[]!").find(c) != std::string_view::npos;
}

std::string parseName(TextCursor &cursor, std::string_view what) {
    cursor.skipSpace();
    if (!isNameStart(cursor.peek())) cursor.fail("expected " + std::string(what) + ", found " + cursor.describeNext());
    std::string name;
    while (isNameChar(cursor.peek())) {
        name += cursor.peek();
        cursor.advance();
    }
    return name;
}

// Parenthesised names: a head's or context word's parameters, a query's.
std::vector<std::string> parseNameList(TextCursor &cursor) {
    std::vector<std::string> names;
    if (cursor.consume(")")) return names;
    do {
        if (names.size() == kMaxWordParameters)
            cursor.fail("more than " + std::to_string(kMaxWordParameters) + " parameters");
        names.push_back(parseName(cursor, "a parameter name"));
    } while (cursor.consume(","));
    cursor.expect(")", "after the parameter names");
    return names;
}

// The line without its `//` comment.
std::string_view withoutComment(std::string_view line) { return line.substr(0, line.find("//")); }

class StreetRuleParser {
  public:
    explicit StreetRuleParser(std::string name) { set_.file = std::move(name); }

    StreetRuleSet parse(std::string_view text) {
        int lineNumber = 0;
        while (!text.empty()) {
            size_t end = std::min(text.find('\n'), text.size());
            TextCursor cursor(withoutComment(text.substr(0, end)), set_.file, ++lineNumber);
            text.remove_prefix(std::min(end + 1, text.size()));
            if (!cursor.atEnd()) parseLine(cursor);
        }
        if (!initialLine_)
            throw InputError({set_.file, 0, 0}, "no initial word (a line 'name: word', e.g. 'o: S(10)')");
        return std::move(set_);
    }

  private:
    void parseLine(TextCursor &cursor) {
        if (cursor.lookingAt("#")) return parseDefine(cursor);
        FileLoc at = cursor.loc();
        std::string label = parseName(cursor, "a label ('p1:') or '#define'");
        cursor.expect(":", "after the label");
        claimLabel(label, at);
        if (!initialLine_) {
            if (cursor.rest().find("->") != std::string_view::npos) {
                throw InputError(at, "a rule before the initial word ('name: word')");
            }
            return parseInitialWord(cursor, label, at);
        }
        if (set_.rules.size() == kMaxStreetRules)
            cursor.fail("more than " + std::to_string(kMaxStreetRules) + " rules");
        set_.rules.push_back(parseRule(cursor, label, at));
    }

    void claimLabel(const std::string &label, const FileLoc &at) {
        auto [it, fresh] = labels_.emplace(label, at.line);
        if (!fresh) throw InputError(at, "label '" + label + "' is already used on line " + std::to_string(it->second));
    }

    // `#define Name value`: the value may be any constant expression of earlier defines.
    void parseDefine(TextCursor &cursor) {
        if (!cursor.consume("#define") || (cursor.peek() != ' ' && cursor.peek() != '\t')) {
            cursor.fail("expected '#define Name value'");
        }
        if (initialLine_)
            cursor.fail("a #define after the initial word (line " + std::to_string(initialLine_) +
                        "): defines come first");
        if (set_.defines.size() == kMaxStreetDefines)
            cursor.fail("more than " + std::to_string(kMaxStreetDefines) + " defines");
        cursor.skipSpace();
        FileLoc at = cursor.loc();
        std::string name = parseName(cursor, "the name of the define");
        if (queryResultNamed(name)) throw InputError(at, "'" + name + "' is a query result code and cannot be defined");
        if (std::ranges::find(set_.defines, name, &Define::name) != set_.defines.end()) {
            throw InputError(at, "'" + name + "' is defined twice");
        }
        Expression value = parseConstant(cursor, "the value of a define");
        if (!cursor.atEnd()) cursor.fail("unexpected " + cursor.describeNext() + " after the define's value");
        set_.defines.push_back({name, value.constantValue()});
    }

    // An expression of numbers and defines alone, ending the line or before `)`, `,`.
    Expression parseConstant(TextCursor &cursor, std::string_view what) {
        Expression expression = Expression::parse(cursor);
        expression.resolveNames({set_.defines, {}});
        if (!expression.isConstant()) {
            throw InputError(expression.loc(),
                             std::string(what) + " must be a constant (numbers and defines), not a random draw");
        }
        return expression;
    }

    void parseInitialWord(TextCursor &cursor, const std::string &label, const FileLoc &at) {
        for (const SuccessorWord &word : parseWords(cursor, "the initial word")) {
            Word &evaluated = set_.initialWord.emplace_back(Word{word.symbol, {}});
            for (const Expression &parameter : word.parameters)
                evaluated.parameters.push_back(parameter.constantValue());
        }
        if (!cursor.atEnd()) cursor.fail(cursor.describeNext() + " is no symbol of a word");
        if (set_.initialWord.empty()) throw InputError(at, "the initial word is empty");
        set_.initialName = label;
        initialLine_ = at.line;
    }

    StreetRule parseRule(TextCursor &cursor, const std::string &label, const FileLoc &at) {
        StreetRule rule;
        rule.label = label;
        rule.loc = at;
        std::vector<WordPattern> words = parsePatterns(cursor);
        if (cursor.consume("<")) {
            if (words.empty()) cursor.fail("expected the left context before '<'");
            rule.leftContext = std::move(words);
            words = parsePatterns(cursor);
        }
        if (words.size() != 1) {
            cursor.fail(words.empty() ? "expected the rule's head, found " + cursor.describeNext()
                                      : "a rule's head is one word, not " + std::to_string(words.size()) +
                                " (a context goes before '<' or after '>')");
        }
        rule.head = std::move(words.front());
        parseRightSide(cursor, rule);
        if (cursor.consume(":")) rule.condition = Expression::parse(cursor);
        if (cursor.consume("{")) rule.assignments = parseAssignments(cursor);
        cursor.expect("->", "between the rule's head and its successor");
        rule.successor = parseWords(cursor, "a successor");
        if (cursor.consume(":")) rule.probability = parseProbability(cursor);
        if (!cursor.atEnd()) cursor.fail("unexpected " + cursor.describeNext() + " in the rule");
        resolveRule(rule);
        return rule;
    }

    // `> right context` or `> ?I(a,len,result)`.
    void parseRightSide(TextCursor &cursor, StreetRule &rule) {
        if (!cursor.consume(">")) return;
        if (cursor.consume("?")) {
            rule.query = parseQuery(cursor);
            return;
        }
        rule.rightContext = parsePatterns(cursor);
        if (rule.rightContext.empty()) cursor.fail("expected the right context or a query '?I(…)' after '>'");
    }

    Query parseQuery(TextCursor &cursor) {
        Query query;
        query.kind = cursor.peek();
        query.loc = cursor.loc();
        if (query.kind != 'I' && query.kind != 'E')
            cursor.fail("unknown query " + cursor.describeNext() + " after '?' (there are ?I and ?E)");
        cursor.advance();
        cursor.expect("(", "after the query's name");
        query.parameters = parseNameList(cursor);
        if (query.parameters.size() != 3) {
            throw InputError(query.loc,
                             fmt::format("?{} takes 3 parameters (angle, length, result), not {}", query.kind,
                                         query.parameters.size()));
        }
        return query;
    }

    // Head and context words: a symbol with optional parameter names; stops at `<`, `>`, `:`,
    // `{`, `->` or anything else that is no symbol.
    std::vector<WordPattern> parsePatterns(TextCursor &cursor) {
        std::vector<WordPattern> words;
        while (!cursor.atEnd() && isSymbol(cursor.peek()) && !cursor.lookingAt("->")) {
            if (isBracket(cursor.peek())) cursor.fail("a bracket cannot be a rule's head or context");
            if (words.size() == kMaxWordsPerRule)
                cursor.fail("more than " + std::to_string(kMaxWordsPerRule) + " words");
            WordPattern &word = words.emplace_back();
            word.symbol = cursor.peek();
            word.loc = cursor.loc();
            cursor.advance();
            if (cursor.consume("(")) word.parameters = parseNameList(cursor);
        }
        return words;
    }

    // `{x = value; y = p ? valueTrue : valueFalse;}`, the opening brace consumed.
    std::vector<Assignment> parseAssignments(TextCursor &cursor) {
        std::vector<Assignment> assignments;
        while (!cursor.consume("}")) {
            if (assignments.size() == kMaxAssignments)
                cursor.fail("more than " + std::to_string(kMaxAssignments) + " assignments");
            cursor.skipSpace();
            Assignment assignment;
            assignment.variable = parseName(cursor, "the name of a variable to assign or '}'");
            cursor.expect("=", "after the variable's name");
            assignment.value = Expression::parse(cursor);
            if (cursor.consume("?")) {
                assignment.probability = std::move(assignment.value);
                assignment.value = Expression::parse(cursor);
                cursor.expect(":", "between the values of 'probability ? value : value'");
                assignment.valueFalse = Expression::parse(cursor);
            }
            assignments.push_back(std::move(assignment));
            if (!cursor.consume(";")) {
                cursor.expect("}", "after an assignment (or ';' before the next)");
                break;
            }
        }
        return assignments;
    }

    // Symbols with parenthesised parameter expressions, brackets balanced; ends at `:` or the
    // end of the line.
    std::vector<SuccessorWord> parseWords(TextCursor &cursor, std::string_view what) {
        std::vector<SuccessorWord> words;
        std::vector<FileLoc> openBrackets;
        while (!cursor.atEnd() && cursor.peek() != ':') {
            char symbol = cursor.peek();
            if (!isSymbol(symbol)) cursor.fail(quoted(symbol) + " is no symbol of a word");
            if (words.size() == kMaxWordsPerRule)
                cursor.fail("more than " + std::to_string(kMaxWordsPerRule) + " words");
            if (symbol == '[') openBrackets.push_back(cursor.loc());
            if (symbol == ']' && openBrackets.empty()) cursor.fail("']' without its '['");
            if (symbol == ']') openBrackets.pop_back();
            cursor.advance();
            SuccessorWord &word = words.emplace_back(SuccessorWord{symbol, {}});
            if (!cursor.consume("(")) continue;
            if (isBracket(symbol)) cursor.fail("a bracket takes no parameters");
            word.parameters = parseParameters(cursor, what);
        }
        if (!openBrackets.empty()) throw InputError(openBrackets.back(), "'[' without its ']'");
        return words;
    }

    // `a, len*1.5)`: the opening parenthesis consumed. The initial word's are constants.
    std::vector<Expression> parseParameters(TextCursor &cursor, std::string_view what) {
        std::vector<Expression> parameters;
        if (cursor.consume(")")) return parameters;
        bool constant = !initialLine_;
        do {
            if (parameters.size() == kMaxWordParameters)
                cursor.fail("more than " + std::to_string(kMaxWordParameters) + " parameters");
            parameters.push_back(constant ? parseConstant(cursor, "a parameter of " + std::string(what))
                                          : Expression::parse(cursor));
        } while (cursor.consume(","));
        cursor.expect(")", "after the parameters");
        return parameters;
    }

    float parseProbability(TextCursor &cursor) {
        Expression expression = parseConstant(cursor, "a rule's probability");
        float p = expression.constantValue();
        if (!(p >= 0 && p <= 1))
            throw InputError(expression.loc(), fmt::format("a rule's probability must lie in [0, 1], not {:.6g}", p));
        return p;
    }

    // Every name of the rule's expressions becomes a define, a result code or one of the
    // rule's variables; a parameter name bound twice is refused.
    void resolveRule(StreetRule &rule) {
        std::vector<std::string> variables;
        for (const auto *words : {&rule.leftContext, &rule.rightContext}) {
            for (const WordPattern &word : *words) bindParameters(word, variables);
        }
        bindParameters(rule.head, variables);
        if (rule.query) addQueryParameters(*rule.query, variables);
        for (const Assignment &assignment : rule.assignments) {
            if (std::ranges::find(variables, assignment.variable) == variables.end())
                variables.push_back(assignment.variable);
        }
        NameScope scope{set_.defines, variables};
        if (rule.condition) rule.condition->resolveNames(scope);
        for (Assignment &assignment : rule.assignments) {
            for (auto *expression : {&assignment.probability, &assignment.valueFalse}) {
                if (*expression) (*expression)->resolveNames(scope);
            }
            assignment.value.resolveNames(scope);
        }
        for (SuccessorWord &word : rule.successor) {
            for (Expression &parameter : word.parameters) parameter.resolveNames(scope);
        }
    }

    static void bindParameters(const WordPattern &word, std::vector<std::string> &variables) {
        for (const std::string &name : word.parameters) {
            if (std::ranges::find(variables, name) != variables.end()) {
                throw InputError(word.loc, "parameter '" + name + "' is bound twice in the rule's head and context");
            }
            variables.push_back(name);
        }
    }

    // The query's in-out parameters may be the head's (`len` in Listing 4.2); within the query
    // each name is used once.
    static void addQueryParameters(const Query &query, std::vector<std::string> &variables) {
        for (size_t i = 0; i < query.parameters.size(); ++i) {
            const std::string &name = query.parameters[i];
            if (std::find(query.parameters.begin(), query.parameters.begin() + i, name) !=
                query.parameters.begin() + i) {
                throw InputError(query.loc, "parameter '" + name + "' is used twice in the query");
            }
            if (std::ranges::find(variables, name) == variables.end()) variables.push_back(name);
        }
    }

    StreetRuleSet set_;
    std::map<std::string, int> labels_;  // label → its line
    int initialLine_ = 0;                // 0 until the initial word is read
};

}  // namespace

StreetRuleSet parseStreetRules(std::string_view text, const std::string &name) {
    return StreetRuleParser(name).parse(text);
}

StreetRuleSet readStreetRuleFile(const std::filesystem::path &file) {
    return parseStreetRules(readInputFile(file), file.string());
}

}  // namespace veduta
