#include "streets/lsystem.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/hash.h"

namespace veduta {

namespace {

bool patternMatches(const WordPattern &pattern, const Word &word) {
    return pattern.symbol == word.symbol && pattern.parameters.size() == word.parameters.size();
}

// The patterns against the words they must equal, in order.
bool contextMatches(std::span<const WordPattern> patterns, std::span<const Word> words) {
    return std::ranges::equal(patterns, words, patternMatches);
}

void bindPattern(const WordPattern &pattern, const Word &word, Bindings &bindings) {
    for (size_t i = 0; i < pattern.parameters.size(); ++i) bindings.set(pattern.parameters[i], word.parameters[i]);
}

// `x = value`, or `x = p ? a : b`: one draw below p takes a. A p outside [0, 1] acts as 0 or 1.
void runAssignment(const Assignment &assignment, Bindings &bindings, WordDraws &draws) {
    const Expression *value = &assignment.value;
    if (assignment.probability) {
        float p = assignment.probability->evaluate(bindings, draws);
        if (!(draws.next() < p)) value = &*assignment.valueFalse;
    }
    bindings.set(assignment.variable, value->evaluate(bindings, draws));
}

// A query parameter without a value yet (`a` in Listing 4.2's p2) enters the query as 0.
void runQuery(const Query &query, const StreetQuery &answer, Bindings &bindings) {
    if (!answer)
        throw InputError(query.loc,
                         fmt::format("?{} needs the street graph, which a plain rewrite has not", query.kind));
    std::vector<float> inOut;
    for (size_t i = 0; i + 1 < query.parameters.size(); ++i) {
        const float *value = bindings.find(query.parameters[i]);
        inOut.push_back(value ? *value : 0.0f);
    }
    QueryResult result = answer(query.kind, inOut);
    for (size_t i = 0; i < inOut.size(); ++i) bindings.set(query.parameters[i], inOut[i]);
    bindings.set(query.parameters.back(), float(result));
}

std::string labels(std::span<const StreetRule *const> rules) {
    std::string text;
    for (const StreetRule *rule : rules) text += (text.empty() ? "" : ", ") + rule->label;
    return text;
}

void warnOnce(std::vector<std::string> &warnings, std::string warning) {
    if (std::ranges::find(warnings, warning) == warnings.end()) warnings.push_back(std::move(warning));
}

}  // namespace

bool headMatches(const StreetRule &rule, std::span<const Word> words, size_t index) {
    size_t left = rule.leftContext.size(), right = rule.rightContext.size();
    return patternMatches(rule.head, words[index]) && index >= left && words.size() - index - 1 >= right &&
        contextMatches(rule.leftContext, words.subspan(index - left, left)) &&
        contextMatches(rule.rightContext, words.subspan(index + 1, right));
}

std::optional<Bindings> applyRule(const StreetRule &rule, std::span<const Word> words, size_t index, WordDraws &draws,
                                  const StreetQuery &query) {
    if (!headMatches(rule, words, index)) return std::nullopt;
    Bindings bindings;
    size_t left = rule.leftContext.size();
    for (size_t i = 0; i < left; ++i) bindPattern(rule.leftContext[i], words[index - left + i], bindings);
    bindPattern(rule.head, words[index], bindings);
    for (size_t i = 0; i < rule.rightContext.size(); ++i)
        bindPattern(rule.rightContext[i], words[index + 1 + i], bindings);
    for (const Assignment &assignment : rule.assignments) runAssignment(assignment, bindings, draws);
    if (rule.query) runQuery(*rule.query, query, bindings);
    if (rule.condition && !rule.condition->isTrue(bindings, draws)) return std::nullopt;
    return bindings;
}

size_t selectByProbability(std::span<const float> probabilities, float draw) {
    float target = draw * std::accumulate(probabilities.begin(), probabilities.end(), 0.0f);
    float cumulative = 0;
    size_t lastPossible = 0;
    for (size_t i = 0; i < probabilities.size(); ++i) {
        cumulative += probabilities[i];
        if (probabilities[i] > 0) lastPossible = i;
        if (target < cumulative) return i;
    }
    return lastPossible;  // a draw that rounding carried past the last cut
}

std::vector<Word> evaluateSuccessor(const StreetRule &rule, const Bindings &bindings, WordDraws &draws) {
    std::vector<Word> successor;
    successor.reserve(rule.successor.size());
    for (const SuccessorWord &word : rule.successor) {
        Word &evaluated = successor.emplace_back(Word{word.symbol, {}});
        for (const Expression &parameter : word.parameters)
            evaluated.parameters.push_back(parameter.evaluate(bindings, draws));
    }
    return successor;
}

std::optional<std::vector<Word>> expandWord(std::span<const Word> words, size_t index,
                                            std::span<const StreetRule> rules, WordDraws &draws,
                                            const StreetQuery &query, std::vector<std::string> &warnings) {
    std::vector<const StreetRule *> matching;
    std::vector<Bindings> bindings;
    for (const StreetRule &rule : rules) {
        if (auto applied = applyRule(rule, words, index, draws, query)) {
            matching.push_back(&rule);
            bindings.push_back(std::move(*applied));
        }
    }
    if (matching.empty()) return std::nullopt;
    std::vector<float> probabilities;
    for (const StreetRule *rule : matching) probabilities.push_back(rule->probability);
    float sum = std::accumulate(probabilities.begin(), probabilities.end(), 0.0f);
    // Built only for a warning: most words meet rules that sum to 1.
    auto warn = [&](std::string_view outcome) {
        warnOnce(warnings,
                 fmt::format("{}: rules {} match a word {} with probabilities summing to {:.6g}{}",
                             matching[0]->loc.toString(), labels(matching), words[index].symbol, sum, outcome));
    };
    if (sum <= 0) {
        warn(": none is applied");
        return std::nullopt;
    }
    if (std::abs(sum - 1) > 1e-4f) warn(", not 1: rescaled");
    // A lone rule needs no choice, and draws nothing for it.
    size_t chosen = matching.size() == 1 ? 0 : selectByProbability(probabilities, draws.next());
    return evaluateSuccessor(*matching[chosen], bindings[chosen], draws);
}

std::vector<Word> rewrite(std::span<const Word> words, const StreetRuleSet &rules, RandomDraws &draws,
                          uint32_t generation, std::vector<std::string> &warnings) {
    std::vector<Word> rewritten;
    for (size_t i = 0; i < words.size(); ++i) {
        WordDraws wordDraws(draws, hashValues({generation, uint32_t(i)}));
        std::optional<std::vector<Word>> successor = expandWord(words, i, rules.rules, wordDraws, {}, warnings);
        if (successor) {
            rewritten.insert(rewritten.end(), successor->begin(), successor->end());
        } else {
            rewritten.push_back(words[i]);
        }
        if (rewritten.size() > kMaxRewrittenWords) {
            throw InputError({rules.file, 0, 0},
                             fmt::format("the rewritten word grew past {} words", kMaxRewrittenWords));
        }
    }
    return rewritten;
}

}  // namespace veduta
