#include "city/generate_city.h"

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "city/assets.h"
#include "city/building_generator.h"
#include "city/city_data.h"
#include "city/lot_subdivision.h"
#include "city/rule_file.h"
#include "city/warning_list.h"
#include "core/hash.h"

namespace veduta {

namespace {

// One of the city's rule files, read once, with the generator that builds with it.
struct RuleFileBuilder {
    RuleSet rules;
    std::unique_ptr<Grammar> grammar;
    std::unique_ptr<BuildingGenerator> generator;
};

std::vector<std::unique_ptr<RuleFileBuilder>> readRuleFiles(const CityDesc &city, const CityData &data,
                                                            RenderSceneBuilder &builder,
                                                            std::vector<std::string> &warnings) {
    if (data.ruleFiles.empty())
        throw InputError(city.fileLoc, "the city names no <Rulefile> to build its lots with");
    const AssetLibrary &assets = AssetLibrary::builtIn();
    std::vector<std::unique_ptr<RuleFileBuilder>> builders;
    for (const std::filesystem::path &file : data.ruleFiles) {
        auto b = std::make_unique<RuleFileBuilder>();
        b->rules = readRuleFile(file, [&](std::string_view name) { return assets.isModelName(name); });
        warnings.insert(warnings.end(), b->rules.warnings.begin(), b->rules.warnings.end());
        b->grammar = std::make_unique<Grammar>(b->rules, [&](std::string_view name) { return assets.findTerminal(name); });
        b->generator = std::make_unique<BuildingGenerator>(*b->grammar, assets, builder, city.seed);
        builders.push_back(std::move(b));
    }
    return builders;
}

// The lots of a block: its own, or perimeter lots cut from it (seed 000's Blockrandbebauung).
std::vector<Footprint> lotsOf(const CityBlock &block, const SettingsStack &blockSettings, uint32_t seed,
                              uint32_t blockIndex) {
    std::vector<Footprint> lots;
    if (!block.lots.empty()) {
        for (const CityLot &lot : block.lots) lots.push_back({lot.points, lot.streetEdges, lot.base});
        return lots;
    }
    Block outline{block.points, block.streetEdges, block.base};
    return perimeterLots(outline, lotSettingsFrom(blockSettings), seed, blockIndex);
}

uint32_t buildCity(const CityDesc &city, uint32_t firstBuildingId, RenderSceneBuilder &builder,
                   std::vector<std::string> &warnings) {
    if (!std::filesystem::is_regular_file(city.file))
        throw InputError(city.fileLoc, fmt::format("cannot read the city file {}", city.file.string()));
    CityData data = readCityData(city.file);
    warnings.insert(warnings.end(), data.warnings.begin(), data.warnings.end());
    auto ruleFiles = readRuleFiles(city, data, builder, warnings);

    uint32_t id = firstBuildingId;
    for (uint32_t b = 0; b < data.blocks.size(); ++b) {
        const CityBlock &block = data.blocks[b];
        SettingsStack blockSettings = settingsFor(data, block, nullptr, ruleFiles.front()->rules.settings);
        std::vector<Footprint> lots = lotsOf(block, blockSettings, city.seed, b);
        for (size_t l = 0; l < lots.size(); ++l, ++id) {
            // Seed 000 picks one of several rule files at random (L1276).
            RuleFileBuilder &rules = *ruleFiles[hashValues({city.seed, id, 0x52554c46u}) % ruleFiles.size()];
            const CityLot *given = block.lots.empty() ? nullptr : &block.lots[l];
            BuildingSpec spec;
            spec.id = id;
            spec.objectId = city.objectId;
            spec.footprint = std::move(lots[l]);
            spec.settings = settingsFor(data, block, given, rules.rules.settings);
            rules.generator->generate(spec, warnings);
        }
    }
    return id - firstBuildingId;
}

}  // namespace

uint32_t generateCity(const CityDesc &city, uint32_t firstBuildingId, RenderSceneBuilder &builder,
                      std::vector<std::string> &out) {
    std::vector<std::string> warnings;
    try {
        uint32_t built = buildCity(city, firstBuildingId, builder, warnings);
        appendOnce(warnings, out);
        return built;
    } catch (const InputError &) {
        appendOnce(warnings, out);  // they may say why
        throw;
    }
}

}  // namespace veduta
