// The rule file reader (docs/rules.md) on any file, and a facade derived with what it reads:
// every rule's predecessor as the start symbol on one facade, within the derivation limits.
#include <memory>
#include <string>
#include <unordered_map>

#include "city/building_settings.h"
#include "city/derivation.h"
#include "city/rule_file.h"
#include "fuzz_input.h"

namespace {

bool isModelName(std::string_view name) { return name.ends_with(".wrl") || name.ends_with(".obj"); }

// Numbers for the model names a rule set uses, as the asset library gives them.
class ModelNumbers {
  public:
    std::optional<uint32_t> operator()(std::string_view name) {
        if (!isModelName(name)) return std::nullopt;
        auto [it, fresh] = numbers_.emplace(std::string(name), uint32_t(numbers_.size()));
        return it->second;
    }

  private:
    std::unordered_map<std::string, uint32_t> numbers_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    using namespace veduta;
    auto file = fuzz::inputFile(data, size, ".xml");
    fuzz::expectInputError([&] {
        RuleSet rules = readRuleFile(file, isModelName);
        ModelNumbers models;
        Grammar grammar(rules, [&](std::string_view name) { return models(name); });
        SettingsStack settings({&rules.settings, &defaultBuildingSettings()});
        const uint32_t seed = 7, building = 1;
        BuildingProperties properties(settings, randomiseHeights(settings, seed, building));
        std::vector<Terminal> terminals;
        std::vector<std::string> warnings;
        for (const Rule &rule : rules.rules) {
            fuzz::expectInputError([&] {
                deriveFacade(grammar, rule.predecessor, {12, 15}, properties, {seed, building}, terminals, warnings,
                             {.maxDepth = 64, .maxShapes = 20000});
            });
            terminals.clear();
        }
    });
    return 0;
}
