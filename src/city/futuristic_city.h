// Goitowski's futuristic cities (Goitowski 2010, L1844–1848, L3946–3963, digest-002 §4): above
// a grown town, parallel street levels that the same rules grow, each with a seed of its own
// (the thesis's "levels about 70 % similar" became one rule set), joined by lifts where a
// neighbour search finds junctions of two levels close enough; their streets are floating
// slabs with crossing solids, their buildings floating prisms of U[7, 18] m. docs/futuristic.md.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "city/city_data.h"
#include "city/grown_city.h"
#include "city/street_geometry.h"
#include "scene/render_scene.h"

namespace veduta {

struct StreetLevels {
    unsigned count = 1;    // levels, the ground's included: 1 is an ordinary town
    float spacing = 40;    // metres from one level's streets to the next's
    float liftReach = 15;  // the farthest apart (in plan) two junctions a lift joins
    float thickness = 1;   // of the floating streets and crossings
};

// An upper level as grown: its streets and blocks (at height 0, as growCity gives them), the
// blocks cut into lots.
struct UpperLevel {
    unsigned index = 1;  // 1: the first above the ground
    uint32_t seed = 0;   // of its growth and its lots
    CityData city;
};

// The seed of level `index` of a city grown with `seed`: level 0, the ground, keeps the city's.
uint32_t levelSeed(uint32_t seed, unsigned index);

// How the ground's streets grew, for the levels above to grow alike: growCity with its rules, or
// traceCity with its field.
using GrowLevel = std::function<CityData(const CityGrowth &, std::vector<std::string> &)>;

// Levels 1 … count − 1, each grown as the ground was, with `ground`'s window and limits but its
// own seed, no environment (they float over slopes and water alike) and no roads, its blocks cut into lots
// with `lotSettings`. Warnings: the growth's and cutLots', each after "level n: ".
std::vector<UpperLevel> growUpperLevels(const GrowLevel &grow, const CityGrowth &ground, unsigned count,
                                        const SettingsMap &lotSettings, std::vector<std::string> &warnings);

// The nodes where three or more streets meet: where a lift may stop.
std::vector<Vec2f> junctionsOf(const StreetNetwork &network);

// A lift: from a junction of one level to one of the level above.
struct Lift {
    Vec3f bottom, top;
};

// The lifts between two levels' junctions: each pair that are each other's nearest (in plan)
// and at most `reach` apart, in the order of the upper junctions.
std::vector<Lift> liftsBetween(std::span<const Vec3f> lower, std::span<const Vec3f> upper, float reach);

// Builds the upper levels over a ground whose junctions lie at `groundJunctions` (heights on the
// terrain, or 0): level i's streets' tops at datum + i · spacing, where the datum is the highest
// ground junction (0 without any), so no level dips into the terrain. Each street a slab, each
// node where two or more streets meet a crossing solid, each lift a platform between two rails,
// each lot a prism (prism_building.h) whose walls show a facade of the scene's category facade,
// one per building (MaterialPalette; rules/futuristic/materials.xml), its roof "prism/roof" and
// its floor "prism/floor"; the slabs and crossings "street/floating" and "street/crossing", the
// lifts "lift/platform" and "lift/rail" (each the scene's material of that name, or a plain one). Building ids are
// cityBuildingId of the object and the lot's identity in its level. Returns how many buildings it built.
uint32_t buildUpperLevels(std::span<const UpperLevel> levels, std::span<const Vec3f> groundJunctions,
                          const StreetLevels &settings, uint32_t seed, ObjectId objectId, RenderSceneBuilder &builder);

}  // namespace veduta
