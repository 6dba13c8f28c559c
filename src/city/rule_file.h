// Reading Bilke's rule files (Rules.xsd, Bilke 2009, §2.2.3) into a RuleSet, with veduta's
// extensions: floating repeats, scope conditions on branches and included files.
// docs/rules.md documents the format and every check.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "city/rules.h"

namespace veduta {

// Knows which terminal names are models (the asset library supplies it); e.g. "Window1.wrl".
using IsModelName = std::function<bool(std::string_view)>;

struct RuleFileLimits {
    int maxIncludeDepth = 16;  // files included by included files …, the top file not counted
};

// Reads `file` and the files it includes, then checks the whole set: every successor is a
// rule's predecessor or a model, and every rule can finish. Throws InputError; what is only
// suspicious goes to RuleSet::warnings.
RuleSet readRuleFile(const std::filesystem::path &file, const IsModelName &isModel, const RuleFileLimits &limits = {});
// The same for rules held in memory (tests, built-in text): `name` is what messages call the
// text, and its includes resolve relative to the current directory.
RuleSet parseRuleFile(std::string xmlText, std::string name, const IsModelName &isModel,
                      const RuleFileLimits &limits = {});

}  // namespace veduta
