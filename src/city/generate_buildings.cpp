#include "city/generate_buildings.h"

#include <filesystem>

#include <fmt/format.h>

#include "city/assets.h"
#include "city/building_generator.h"
#include "city/building_rules.h"
#include "city/party_walls.h"
#include "city/plinth.h"
#include "city/warning_list.h"

namespace veduta {

namespace {

Footprint footprintOf(const BuildingDesc &building, const GroundHeight &ground, std::vector<std::string> &warnings) {
    Footprint footprint;
    footprint.points = building.footprint;
    footprint.streetEdges.assign(building.footprint.size(), false);
    for (uint32_t edge : building.streetEdges) footprint.streetEdges[edge] = true;
    if (auto warning = normaliseFootprint(footprint, building.footprintLoc)) warnings.push_back(*warning);
    if (building.base) {
        footprint.base = *building.base;
    } else if (ground) {
        std::optional<float> datum = ground(footprint.points);
        if (!datum) {
            warnings.push_back(fmt::format("{}: building {} stands off the terrain; it is placed at height 0",
                                           building.loc.toString(), building.buildingId));
        }
        footprint.base = datum.value_or(0.0f);
    }
    return footprint;
}

// What the group costs its author: the rule file's lines, and the numbers the scene gives its
// buildings (settings, footprint coordinates, bases).
ModelEffort effortOf(const BuildingGroupDesc &group) {
    ModelEffort effort;
    effort.ruleLines = ruleFileLines(group.rules);
    effort.parameters = group.settings.size();
    for (const BuildingDesc &building : group.buildings)
        effort.parameters += building.settings.size() + 2 * building.footprint.size() + (building.base ? 1 : 0);
    for (const FacadeDesc &facade : group.facades) effort.parameters += facade.settings.size() + 2;
    return effort;
}

void generateGroup(const BuildingGroupDesc &group, uint32_t seed, const GroundHeight &ground,
                   RenderSceneBuilder &builder, std::vector<std::string> &warnings, const Camera *camera,
                   const MasonryOutput &masonryMaps) {
    if (!std::filesystem::is_regular_file(group.rules))
        throw InputError(group.rulesLoc, fmt::format("cannot read the rule file {}", group.rules.string()));
    BuildingRules loaded(group.rules);
    const RuleSet &rules = loaded.rules;
    const Grammar &grammar = loaded.grammar;
    warnings.insert(warnings.end(), rules.warnings.begin(), rules.warnings.end());
    BuildingGenerator generator(grammar, AssetLibrary::builtIn(), builder, seed);
    if (camera && masonryMaps) generator.bakeMasonryWith(*camera, masonryMaps);
    builder.addEffort(effortOf(group));
    std::vector<BuildingSpec> specs;
    for (const BuildingDesc &desc : group.buildings) {
        BuildingSpec &spec = specs.emplace_back();
        spec.id = desc.buildingId;
        spec.objectId = desc.objectId;
        spec.footprint = footprintOf(desc, ground, warnings);
        spec.settings = SettingsStack({&desc.settings, &group.settings, &rules.settings, &defaultBuildingSettings()});
    }
    std::vector<const Footprint *> footprints;
    for (const BuildingSpec &spec : specs) footprints.push_back(&spec.footprint);
    std::vector<std::vector<bool>> party = partyWalls(footprints);
    for (size_t b = 0; b < specs.size(); ++b) specs[b].partyEdges = std::move(party[b]);
    for (size_t b = 0; b < specs.size(); ++b) {
        const BuildingDesc &desc = group.buildings[b];
        buildAt(desc.loc, [&] { generator.generate(specs[b], warnings); });
        if (!desc.base && ground) addPlinth(specs[b], builder);
    }
    // The facade frame (right, up, out) standing on the x axis and facing −y.
    const Transform standing{{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0}};
    for (const FacadeDesc &desc : group.facades) {
        FacadeSpec spec;
        spec.id = desc.buildingId;
        spec.objectId = desc.objectId;
        spec.startSymbol = desc.start;
        spec.width = desc.width;
        spec.height = desc.height;
        spec.facadeToWorld = desc.transform * standing;
        spec.settings = SettingsStack({&desc.settings, &group.settings, &rules.settings, &defaultBuildingSettings()});
        if (!grammar.findRule(desc.start))
            throw InputError(desc.loc, fmt::format("the rule file has no rule for the start symbol '{}'", desc.start));
        generator.generateFacade(spec, warnings);
    }
}

}  // namespace

void generateBuildings(const BuildingGroupDesc &group, uint32_t seed, const GroundHeight &ground,
                       RenderSceneBuilder &builder, std::vector<std::string> &out, const Camera *camera,
                       const MasonryOutput &masonryMaps) {
    std::vector<std::string> warnings;
    try {
        generateGroup(group, seed, ground, builder, warnings, camera, masonryMaps);
    } catch (const InputError &) {
        appendOnce(warnings, out);  // they may say why
        throw;
    }
    appendOnce(warnings, out);
}

}  // namespace veduta
