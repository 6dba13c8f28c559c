// A rule file read and checked against the built-in models, with its grammar: what the
// building generator derives buildings from. Not copyable or movable: the grammar points into
// the rules.
#pragma once

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

}  // namespace veduta
