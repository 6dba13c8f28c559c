// A rule file read and checked against the built-in models, with its grammar: what the
// building generator derives buildings from. Not copyable or movable: the grammar points into
// the rules.
#pragma once

#include <cstdint>
#include <filesystem>

#include "city/derivation.h"
#include "city/rules.h"

namespace veduta {

struct BuildingRules {
    // Throws InputError for a file that cannot be read or rules that are wrong; the rules'
    // warnings are in `rules.warnings`.
    explicit BuildingRules(const std::filesystem::path &file);
    BuildingRules(const BuildingRules &) = delete;
    BuildingRules &operator=(const BuildingRules &) = delete;

    RuleSet rules;
    Grammar grammar;
};

// The lines of a rule file that hold anything: what a rule set costs its author to write
// (`veduta compare`'s effort, docs/compare.md). 0 for a file that cannot be read.
uint64_t ruleFileLines(const std::filesystem::path &file);

}  // namespace veduta
