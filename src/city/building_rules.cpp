#include "city/building_rules.h"

#include "city/assets.h"
#include "city/rule_file.h"

namespace veduta {

namespace {

const AssetLibrary &models() { return AssetLibrary::builtIn(); }

}  // namespace

BuildingRules::BuildingRules(const std::filesystem::path &file) :
    rules(readRuleFile(file, [](std::string_view name) { return models().isModelName(name); })),
    grammar(rules, [](std::string_view name) { return models().findTerminal(name); }) {}

}  // namespace veduta
