#include "city/building_rules.h"

#include <fstream>
#include <string>

#include "city/assets.h"
#include "city/rule_file.h"

namespace veduta {

namespace {

const AssetLibrary &models() { return AssetLibrary::builtIn(); }

}  // namespace

BuildingRules::BuildingRules(const std::filesystem::path &file) :
    rules(readRuleFile(file, [](std::string_view name) { return models().isModelName(name); })),
    grammar(rules, [](std::string_view name) { return models().findTerminal(name); }) {}

uint64_t ruleFileLines(const std::filesystem::path &file) {
    uint64_t lines = 0;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (line.find_first_not_of(" \t\r") != std::string::npos) ++lines;
    return lines;
}

}  // namespace veduta
