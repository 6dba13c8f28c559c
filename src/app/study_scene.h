// The scenes `veduta facade`, `veduta building` and `veduta export --rules` make around one
// facade or one building: the rule file, settings from the command line, the rule set's
// materials, a ground, a sun from the front left and a camera that frames it all.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "description/scene_description.h"

namespace veduta {

struct StudyOptions {
    std::string rules;
    uint32_t seed = 0;
    uint32_t id = 1;                    // the building id: with the seed, its random choices
    std::vector<std::string> settings;  // Name=Value, above the rule file's own
    std::string materials;              // a material file; default: materials.xml beside the rules
};

struct BuildingOptions {
    std::vector<float> footprint;  // x y pairs
    std::vector<uint32_t> street;  // street edges
};

// RULEFILE (or, with `asOption`, --rules RULEFILE), --seed, --id, --set, --materials.
void addStudyOptions(CLI::App &command, StudyOptions &options, bool rulesAsOption = false);
// --footprint (required unless told otherwise), --street.
void addFootprintOptions(CLI::App &command, BuildingOptions &options, bool required = true);

SceneDescription facadeStudy(const StudyOptions &options, const std::string &start, float width, float height);
// The building alone: its rules, settings and materials, no ground, camera or sun.
SceneDescription buildingScene(const StudyOptions &options, const BuildingOptions &building);
// The building with a ground, a sun from the front left and a camera framing it.
SceneDescription buildingStudy(const StudyOptions &options, const BuildingOptions &building);

}  // namespace veduta
