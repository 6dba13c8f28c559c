// A street L-system as its rule file describes it (Goitowski 2010, Listing 4.2): the defines,
// the initial word and the rules, and the words the rules rewrite. street_rule_file.h reads
// the file; lsystem.h matches, chooses and evaluates the rules.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "streets/expression.h"

namespace veduta {

// A word of the L-system's string: a one-character symbol (F, f, +, -, &, ^, /, \, |, [, ], or
// a letter such as S, P, A) and its evaluated parameters: F(10), +(0.468), [.
struct Word {
    char symbol = 0;
    std::vector<float> parameters;
};

// The thesis' form: `+(0.468)F(15)[`; parameters with up to six significant digits.
std::string toString(std::span<const Word> words);

// A word in a rule's head or context: its symbol and the names its parameters take.
struct WordPattern {
    char symbol = 0;
    std::vector<std::string> parameters;
    FileLoc loc;
};

// `?I(a,len,result)` or `?E(…)`: the environment query of a sensitive rule. The caller's
// StreetQuery (lsystem.h) answers it.
struct Query {
    char kind = 0;                        // 'I': the system's own graph; 'E': the environment
    std::vector<std::string> parameters;  // in-out values, then the result's name
    FileLoc loc;
};

// `x = value` or `x = p ? valueTrue : valueFalse`: with probability p (a number in [0, 1],
// one draw) x takes valueTrue, else valueFalse.
struct Assignment {
    std::string variable;
    std::optional<Expression> probability;
    Expression value;                      // the value, or valueTrue
    std::optional<Expression> valueFalse;  // with `probability`
};

// A word of a successor, its parameters still expressions: &(a), F(len*1.5), [.
struct SuccessorWord {
    char symbol = 0;
    std::vector<Expression> parameters;
};

// `label: [left <] Head(params) [> right | > ?Query(params)] [: condition] [{assignments}]
//  -> successor [: probability]`
struct StreetRule {
    std::string label;
    FileLoc loc;
    std::vector<WordPattern> leftContext;  // the words just before the head, in order
    WordPattern head;
    std::vector<WordPattern> rightContext;  // the words just after it
    std::optional<Query> query;
    std::optional<Expression> condition;
    std::vector<Assignment> assignments;  // run in order, before the query
    std::vector<SuccessorWord> successor;
    float probability = 1;  // its weight among the rules that match a word
};

struct StreetRuleSet {
    std::string file;  // what messages call the rule file
    std::vector<Define> defines;
    std::string initialName;  // `o` of `o: S(10)`
    std::vector<Word> initialWord;
    std::vector<StreetRule> rules;
};

}  // namespace veduta
