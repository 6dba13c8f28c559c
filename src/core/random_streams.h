// The named streams of every random choice (issue 16): each hash that draws takes its stream's
// tag among its inputs, so that choices made with one seed and one identity never share
// numbers. The identities generated things take from their sources are hashed the same way
// and have tags here too. docs/ARCHITECTURE.md, "Determinism", says how seeds and ids are
// formed. The tags that existed before this header keep their values (most spell four ASCII
// letters), so that images whose seeds and ids did not change stayed as they were.
#pragma once

#include <cstdint>

namespace veduta {

// Add a new stream to kAllRandomStreams as well: a test checks that no two tags are equal.
enum class RandomStream : uint32_t {
    // The sampler: pixel seeds hash the seed times this odd tag (a bijection that keeps 0, and
    // with it every image rendered with seed 0 before the tag), not the tag as an input.
    Sampler = 0x50495853u,               // "PIXS": a pixel's Sobol scrambles (render/sampler.h)
    RuleBranches = 0x52554c45u,          // "RULE": the branch a rule takes in a building
    RuleFileChoice = 0x52554c46u,        // "RULF": which of a city's rule files builds a lot
    BuildingHeights = 0x48454947u,       // "HEIG": a building's height, floor and roof heights within their Var
    MaterialPalette = 0x4d41544cu,       // "MATL": a building's material of each category
    RoofChoice = 0x524f4f46u,            // "ROOF": the roof type drawn from a RoofType list
    LotHousingDensity = 0x6c6f7473u,     // "lots": whether a lot is kept (HousingDensity)
    LotPerimeterFrontage = 0x4c504552u,  // "LPER": the frontages of perimeter lots along a block's street
    LotRecursiveSplit = 0x4c524543u,     // "LREC": where the recursive and OBB subdivisions cut (the root key)
    LotObbTurned = 0x4f424254u,          // "OBBT": the OBB subdivision's retry across the shorter axis
    LotSkeletonFrontage = 0x4c534b45u,   // "LSKE": the frontages of straight-skeleton strips
    TreeModel = 0x5452454du,             // "TREM": the key of a tree prototype (kind, variant)
    TreeRewrite = 1,                     // a tree's L-system productions (under its TreeModel key)
    TreeTurtle = 2,                      // a tree's angle, length and width jitter (under its TreeModel key)
    TreePlacement = 0x54524550u,         // "TREP": a tree's place, kind, variant, size and turn in its object
    StreetRules = 0x5354524cu,           // "STRL": a street L-system's U[], random(), assignment odds and rule choice
    StreetLevel = 0x534c564cu,           // "SLVL": the seed of a futuristic city's upper street level
    LiftStop = 0x4c494654u,              // "LIFT": where a lift's platform stands on its way
    TensorNoise = 0x544e5349u,           // "TNSI": the noise that turns a tensor field's directions
    TensorLayout = 0x544c4159u,          // "TLAY": the basis fields of a seeded tensor-field town
    SlgPlan = 0x534c4750u,               // "SLGP": a Spatial Landmark Graph's landmark jitter (slg/landmarks.h)
    SlgParameters = 0x534c4756u,         // "SLGV": the rand() of Schrader's parameter cascade (slg/urban_geography.h)
    MasonryBricks = 0x4d42524bu,         // "MBRK": a brick's colour within its Brick's range (facade/brick_bond.h)
    MasonryAshlar = 0x4d41534cu,         // "MASL": an ashlar stone's size and colour (facade/ashlar.h)
    MasonryCyclopean = 0x4d435943u,      // "MCYC": a cyclopean wall's seeds and stone colours (facade/cyclopean.h)

    // Identities: not random, but hashed like the draws and kept apart from them.
    CityDataBlock = 0x4344424bu,  // "CDBK": a CityData block, from the ids of its outline's points
    CityDataLot = 0x43444c54u,    // "CDLT": a CityData lot, from the ids of its outline's points
    OsmWay = 0x4f534d57u,         // "OSMW": a block or lot from an OpenStreetMap way (its id, its part)
    OsmRelation = 0x4f534d52u,    // "OSMR": a block or lot from an OpenStreetMap relation
    CutLot = 0x4355544cu,         // "CUTL": a lot cut from a block: the block's identity and its path in it
    CityBuilding = 0x43424c44u,   // "CBLD": a city building's id: its city and its lot's identity
    AtkisGeometry = 0x41544b47u,  // "ATKG": an ATKIS object without an id, from its Objektart and geometry
};

inline constexpr RandomStream kAllRandomStreams[] = {
    RandomStream::Sampler,
    RandomStream::RuleBranches,
    RandomStream::RuleFileChoice,
    RandomStream::BuildingHeights,
    RandomStream::MaterialPalette,
    RandomStream::RoofChoice,
    RandomStream::LotHousingDensity,
    RandomStream::LotPerimeterFrontage,
    RandomStream::LotRecursiveSplit,
    RandomStream::LotObbTurned,
    RandomStream::LotSkeletonFrontage,
    RandomStream::TreeModel,
    RandomStream::TreeRewrite,
    RandomStream::TreeTurtle,
    RandomStream::TreePlacement,
    RandomStream::StreetRules,
    RandomStream::StreetLevel,
    RandomStream::LiftStop,
    RandomStream::TensorNoise,
    RandomStream::TensorLayout,
    RandomStream::SlgPlan,
    RandomStream::SlgParameters,
    RandomStream::MasonryBricks,
    RandomStream::MasonryAshlar,
    RandomStream::MasonryCyclopean,
    RandomStream::CityDataBlock,
    RandomStream::CityDataLot,
    RandomStream::OsmWay,
    RandomStream::OsmRelation,
    RandomStream::CutLot,
    RandomStream::CityBuilding,
    RandomStream::AtkisGeometry,
};

// The tag as a hash input: hashValues({seed, id, streamTag(RandomStream::RoofChoice)}).
constexpr uint32_t streamTag(RandomStream stream) { return uint32_t(stream); }

static_assert(streamTag(RandomStream::Sampler) % 2 == 1, "the sampler's tag multiplies the seed: it must be odd");

}  // namespace veduta
