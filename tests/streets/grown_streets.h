// Street networks grown for the tests, and the properties issue 20 asks of every one.
#pragma once

#include <string>

#include "streets/street_builder.h"
#include "streets/street_constraints.h"
#include "streets/street_graph.h"
#include "streets/street_growth.h"
#include "streets/street_rules.h"

namespace veduta::test {

// The text of a pattern shipped in rules/streets/ ("grid", "organic", "radial").
std::string patternText(const std::string &name);

// A rule set grown with the constraints inside a window round the origin.
struct GrownStreets {
    // The environment, when given, must outlive the town.
    GrownStreets(const std::string &rulesText, RandomDraws &draws, const StreetEnvironment *environment = nullptr);
    GrowthResult grow(float radius, size_t expansions = kMaxRewrittenWords);

    StreetRuleSet rules;
    WordGraph words;
    StreetBuilder streets;
    StreetGrowth growth;
};

// On one level: no two edges meet but at a shared vertex, none is shorter than minLength, and
// the edges at every vertex are at least minAngleDegrees apart.
void expectSoundNetwork(const StreetGraph &graph, const StreetConstraints &constraints = {});

}  // namespace veduta::test
