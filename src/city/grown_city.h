// A city grown from a street L-system (issue 20, seed 002): the street graph the rules grow
// inside a window under the local constraints (src/streets/, docs/street-rules.md), its blocks
// as the faces of that graph (docs/street-blocks.md), and the CityData that generateCity cuts
// into lots and builds, as it builds a CityData file. docs/grown-city.md.
#pragma once

#include <string>
#include <vector>

#include "city/city_data.h"
#include "core/vecmath.h"
#include "streets/street_builder.h"
#include "streets/street_constraints.h"
#include "streets/street_graph.h"
#include "streets/street_growth.h"
#include "streets/street_hierarchy.h"
#include "streets/street_rules.h"
#include "streets/tensor_field.h"
#include "streets/tensor_streets.h"

namespace veduta {

struct CityGrowth {
    // Where the rules' origin lies, metres from the scene origin (x east, y north): the window
    // is centred on it, and the city is moved there.
    Vec2f centre;
    float radius = 500;  // of the window
    uint32_t seed = 0;   // of every draw of the rules
    StreetConstraints constraints;
    GrowthLimits limits;
    StreetHierarchy hierarchy;  // the widths of main and minor streets
    // The ground the streets may not cross (ground_environment.h), in the rules' frame; none:
    // open ground everywhere. It must outlive growCity.
    const StreetEnvironment *environment = nullptr;
    // The roads already there (existingRoads, ground_environment.h), in the rules' frame: growCity
    // seeds them into the street graph as static streets that the rules' streets meet, and they
    // become streets of the city. traceCity does not take them yet.
    std::vector<std::vector<Vec2f>> roads;
};

// What the growth came to, besides the city.
struct CityGrowthReport {
    GrowthResult growth;
    StreetCounts streets;
    StreetGraph graph;  // all of it, every level, in the rules' frame (not moved to the centre)
    size_t majorStreets = 0;
    size_t blocks = 0;
    size_t blocksWithStreetsInside = 0;  // left out: generateCity cuts no block with a hole
    size_t otherLevelStreets = 0;        // left out: only the ground level becomes a city yet
    size_t streamlines = 0;              // traced (traceCity); 0 for a town grown by rules
};

// The city the rules grow: a point per street vertex (heights 0: generateCity puts the city on
// a landscape's terrain), a street per street edge of the ground level, of the main or minor
// width by the hierarchy (street_hierarchy.h), a block per bounded face of those streets, without lots (generateCity
// cuts them by the blocks' LotSubdivision). Warnings: the rule choice's, a growth stopped by a limit, what was left out
// and why.
CityData growCity(const StreetRuleSet &rules, const CityGrowth &growth, std::vector<std::string> &warnings,
                  CityGrowthReport *report = nullptr);

// The same for streets traced through a tensor field (tensor_streets.h; docs/tensor-streets.md)
// in the rules' frame, instead of grown by rules: the window, centre, seed, constraints,
// hierarchy and environment of `growth` as growCity takes them (its limits are the rules').
CityData traceCity(const TensorField &field, const StreamlineSettings &settings, const CityGrowth &growth,
                   std::vector<std::string> &warnings, CityGrowthReport *report = nullptr);

}  // namespace veduta
