// Applying street rules to words (Goitowski 2010, §4.2.3): which rules match a word, which of
// them is chosen, and the successor the chosen one gives. The geometric expansion (the turtle,
// the graph, the window) calls expandWord with its own StreetQuery; rewrite() is the plain
// parallel step of a system without queries.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "streets/query_result.h"
#include "streets/random_draws.h"
#include "streets/street_rules.h"

namespace veduta {

// Answers a rule's ?I or ?E: `kind` is its letter, `inOut` the values of all its parameters
// but the last (angle, length), which it may correct; the code it returns becomes the last
// parameter's value.
using StreetQuery = std::function<QueryResult(char kind, std::span<float> inOut)>;

// The words a rewrite may produce, so that a runaway system fails with a message.
inline constexpr size_t kMaxRewrittenWords = size_t(1) << 22;

// Symbol, arity and the plain-word contexts (the adjacent words, brackets not skipped).
bool headMatches(const StreetRule &rule, std::span<const Word> words, size_t index);

// The rule's variables for words[index] if it applies: the head matches, the assignments run,
// then the query, and the condition holds. Throws InputError from the expressions, or when
// the rule has a query and `query` is empty.
std::optional<Bindings> applyRule(const StreetRule &rule, std::span<const Word> words, size_t index, WordDraws &draws,
                                  const StreetQuery &query);

// The rule that `draw` (in [0, 1)) picks when the probabilities are laid out on [0, 1] in
// order, scaled to sum to 1: (0.15, 0.5, 0.35) cut at 0.15 and 0.65. Needs a positive sum.
size_t selectByProbability(std::span<const float> probabilities, float draw);

std::vector<Word> evaluateSuccessor(const StreetRule &rule, const Bindings &bindings, WordDraws &draws);

// The successor of words[index], or nothing when no rule applies. When the probabilities of
// the applying rules do not sum to 1 they are rescaled and `warnings` gets a line (once).
std::optional<std::vector<Word>> expandWord(std::span<const Word> words, size_t index,
                                            std::span<const StreetRule> rules, WordDraws &draws,
                                            const StreetQuery &query, std::vector<std::string> &warnings);

// One parallel step: every word replaced by its successor, or kept. Word i of step
// `generation` draws as the word hashValues({generation, i}).
std::vector<Word> rewrite(std::span<const Word> words, const StreetRuleSet &rules, RandomDraws &draws,
                          uint32_t generation, std::vector<std::string> &warnings);

}  // namespace veduta
