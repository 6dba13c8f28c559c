// Reading a street rule file (Goitowski 2010, Listing 4.2) into a StreetRuleSet: the defines,
// then the initial word, then one rule per line. docs/street-rules.md documents the format,
// the choices made where the thesis leaves it open, and every check.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "streets/street_rules.h"

namespace veduta {

// What a file may hold, so that a hostile file is refused with a message, not a crash.
inline constexpr size_t kMaxStreetRules = 10000;
inline constexpr size_t kMaxStreetDefines = 10000;
inline constexpr size_t kMaxWordsPerRule = 10000;  // in a successor, a context or the initial word
inline constexpr size_t kMaxWordParameters = 32;
inline constexpr size_t kMaxAssignments = 256;  // in one rule's braces

// Throws InputError "file:line:col: what is wrong".
StreetRuleSet readStreetRuleFile(const std::filesystem::path &file);
// The same for text in memory; `name` is what messages call it.
StreetRuleSet parseStreetRules(std::string_view text, const std::string &name);

}  // namespace veduta
