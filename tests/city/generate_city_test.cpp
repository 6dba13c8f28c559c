// <city> in scene files: Bilke's Listing 2.1 built into lots, buildings and streets.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>

#include "assembly/build_scene.h"
#include "city/generate_city.h"
#include "input_error.h"
#include "scene/scene_hash.h"
#include "shared_data.h"
#include "test_paths.h"

namespace veduta {
namespace {

RenderScene build(const std::string &xml, std::vector<std::string> *warnings = nullptr) {
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), warnings);
}

TEST(GenerateCity, ListingTwoOneBecomesLotsBuildingsAndStreets) {
    std::vector<std::string> warnings;
    RenderScene scene = build(
        "<scene version=\"1\"><city file=\"../cities/bilke-listing-2-1.xml\" seed=\"1909\"/>"
        "<buildings rules=\"../rules/gruenderzeit/FacadeStructure.xml\"><building id=\"5\" "
        "footprint=\"-60 -60 -45 -60 -45 -48 -60 -48\" street=\"0\"/></buildings></scene>",
        &warnings);
    std::set<uint32_t> buildings;
    for (const BakedMesh &m : scene.meshes) buildings.insert(m.buildingId);
    // The scene's own building keeps 5; the city's, the given lot and the lots cut from the first
    // block, take ids hashed from their lots, which the float IndexBuilding pass holds exactly;
    // the streets are no building.
    EXPECT_TRUE(buildings.count(5));
    EXPECT_TRUE(buildings.count(0));
    EXPECT_GE(buildings.size(), 4u);
    EXPECT_LT(*buildings.rbegin(), 1u << 24);
    bool clockwise = false;
    for (const std::string &w : warnings)
        clockwise |= w.find("bilke-listing-2-1.xml:63:7: the block runs clockwise") != std::string::npos;
    EXPECT_TRUE(clockwise);
}

// Two real footways (MANIFEST.md) whose street surface crashed the float triangulation of
// its rounded outlines: a closed way and a short one below it.
TEST(GenerateCity, TwoRealFootwaysGiveAStreetSurface) {
    std::optional<std::filesystem::path> file = test::sharedDataFile("osm/two_footways.osm");
    if (!file) GTEST_SKIP() << "../shared/data/osm/two_footways.osm is not there";
    RenderScene scene =
        build(fmt::format("<scene version=\"1\"><city file=\"{}\" "
                          "rules=\"../rules/gruenderzeit/FacadeStructure.xml\"/></scene>",
                          file->string()));
    size_t streetTriangles = 0;
    for (const BakedMesh &m : scene.meshes)
        if (m.buildingId == 0) streetTriangles += m.mesh.triangleCount();
    EXPECT_GT(streetTriangles, 0u);
}

TEST(GenerateCity, AnOpenStreetMapFileIsACityWithTheRulesOfItsElement) {
    std::vector<std::string> warnings;
    RenderScene scene = build(
        "<scene version=\"1\"><city file=\"../tests/data/osm/small-district.osm\" "
        "rules=\"../rules/gruenderzeit/FacadeStructure.xml\" seed=\"3\"/></scene>",
        &warnings);
    std::set<uint32_t> buildings;
    for (const BakedMesh &m : scene.meshes) buildings.insert(m.buildingId);
    EXPECT_TRUE(buildings.count(0));  // the streets
    EXPECT_GE(buildings.size(), 4u);
    try {
        build("<scene version=\"1\"><city file=\"../tests/data/osm/small-district.osm\"/></scene>");
        ADD_FAILURE() << "a city without rules was built";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("test.xml:1:32: the city names no <Rulefile>"), std::string::npos)
            << e.what();
    }
}

// Two lots whose identities hash to one building id: the second is warned about at its place.
TEST(GenerateCity, TwoLotsOfOneIdAreWarnedAbout) {
    std::unordered_map<uint32_t, uint32_t> identityOfId;
    uint32_t first = 0, second = 0;
    for (uint32_t identity = 1; !second; ++identity) {  // a few thousand, by the birthday bound
        auto [it, fresh] = identityOfId.emplace(cityBuildingId(1, identity), identity);
        if (!fresh) first = it->second, second = identity;
    }
    CityData data = parseCityData(R"(<CityData><Points>
        <Point id="0" e="0" n="0"/><Point id="1" e="40" n="0"/><Point id="2" e="40" n="20"/>
        <Point id="3" e="0" n="20"/><Point id="4" e="20" n="0"/><Point id="5" e="20" n="14"/>
        <Point id="6" e="0" n="14"/><Point id="7" e="40" n="14"/>
        </Points><Blocks><Block><Points><Point id="0"/><Point id="1"/><Point id="2"/><Point id="3"/></Points><Lots>
        <Lot><Points><Point id="0" streetEdge="1"/><Point id="4"/><Point id="5"/><Point id="6"/></Points></Lot>
        <Lot><Points><Point id="4" streetEdge="1"/><Point id="1"/><Point id="7"/><Point id="5"/></Points></Lot>
        </Lots></Block></Blocks><Rulefiles><Rulefile>FacadeStructure.xml</Rulefile></Rulefiles></CityData>)",
                                  "ids.xml", test::sourceFile("rules/gruenderzeit"));
    data.blocks[0].lots[0].sourceId = first;
    data.blocks[0].lots[1].sourceId = second;
    RenderSceneBuilder builder;
    std::vector<std::string> warnings;
    EXPECT_EQ(generateCity(data, 0, 1, builder, warnings), 2u);
    std::string expected = fmt::format(
        "ids.xml:7:9: this lot's building has the id {} of the one at ids.xml:6:9 (a "
        "hash collision)",
        cityBuildingId(1, first));
    bool warned = false;
    for (const std::string &w : warnings) warned |= w.find(expected) != std::string::npos;
    EXPECT_TRUE(warned) << fmt::format("{}", fmt::join(warnings, "\n"));
}

TEST(GenerateCity, StreetsJoinThePointsTheyName) {
    // Ids out of file order and with gaps: streets must not take them for positions.
    CityData data = parseCityData(
        "<CityData><Points><Point id=\"30\" e=\"0\" n=\"0\"/><Point id=\"7\" e=\"50\" n=\"0\"/>"
        "<Point id=\"12\" e=\"50\" n=\"40\"/></Points><StreetNetwork><Streets>"
        "<Street id=\"0\" startPoint=\"7\" endPoint=\"12\"/></Streets></StreetNetwork></CityData>",
        "ids.xml", ".");
    StreetNetwork network = streetNetworkOf(data);
    ASSERT_EQ(network.streets.size(), 1u);
    Vec2f from = network.nodes[network.streets[0].from], to = network.nodes[network.streets[0].to];
    EXPECT_EQ(from.x, 50);
    EXPECT_EQ(from.y, 0);
    EXPECT_EQ(to.x, 50);
    EXPECT_EQ(to.y, 40);
}

// A row of 600 lots on one block: three batches of buildings, one added while the others make
// the next. `unbuildable` lots get a roof type that is none.
CityData rowOfLots(const std::vector<int> &unbuildable) {
    CityData data;
    constexpr int kLots = 600;
    CityBlock block;
    block.points = {{0, 0}, {12.0f * kLots, 0}, {12.0f * kLots, 14}, {0, 14}};
    for (int i = 0; i < kLots; ++i) {
        float x = 12.0f * float(i);
        CityLot lot;
        lot.points = {{x, 0}, {x + 12, 0}, {x + 12, 14}, {x, 14}};
        lot.streetEdges = {true, false, false, false};
        lot.loc = {"lots.xml", i + 1, 1};
        lot.sourceId = uint32_t(i + 1);
        if (std::count(unbuildable.begin(), unbuildable.end(), i))
            lot.settings["RoofType"] = settingValue("bogus", {"lots.xml", i + 1, 5});
        block.lots.push_back(std::move(lot));
    }
    data.blocks.push_back(std::move(block));
    data.ruleFiles = {test::sourceFile("rules/gruenderzeit/FacadeStructure.xml")};
    return data;
}

// Lots 300 and 520 cannot be built: the error thrown is lot 300's, the first in lot order, on
// one thread and on two.
TEST(GenerateCity, TheFirstErrorInLotOrderIsThrownOnAnyNumberOfThreads) {
    CityData data = rowOfLots({300, 520});
    for (size_t threads : {1, 2}) {
        SCOPED_TRACE(threads);
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        RenderSceneBuilder builder;
        std::vector<std::string> warnings;
        std::string error = test::inputErrorOf([&] { generateCity(data, 0, 1, builder, warnings); });
        EXPECT_EQ(error.rfind("lots.xml:301:1: this building cannot be built: lots.xml:301:5: RoofType 'bogus'", 0), 0u)
            << error;
    }
}

// The buildings of three batches are added in lot order however they were made.
TEST(GenerateCity, BatchesOfBuildingsAreTheSameOnAnyNumberOfThreads) {
    CityData data = rowOfLots({});
    auto builtOn = [&](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        RenderSceneBuilder builder;
        std::vector<std::string> warnings;
        EXPECT_EQ(generateCity(data, 0, 1, builder, warnings), 600u);
        return std::move(builder).build();
    };
    RenderScene one = builtOn(1), two = builtOn(2);
    EXPECT_GT(one.instances.size(), 600u);
    EXPECT_EQ(one.meshes.size(), two.meshes.size());
    EXPECT_EQ(one.instances.size(), two.instances.size());
    EXPECT_EQ(sceneHash(one), sceneHash(two));
}

// The row of 600 lots runs 7.2 km east from the origin; this camera stands at its west end,
// looking along it.
Camera atTheWestEnd(int width = 640, int height = 360) {
    Camera camera;
    camera.position = {0, -20, 2};
    camera.lookAt = {100, 20, 2};
    camera.width = width;
    camera.height = height;
    return camera;
}

TEST(GenerateCity, BuildingsBeyondCoarseBeyondAreBoxesInOneMesh) {
    CityData data = rowOfLots({});
    RenderSceneBuilder builder;
    std::vector<std::string> warnings;
    generateCity(data, 0, 1, builder, warnings, nullptr, {atTheWestEnd(), CoarseRule{300.0f, 0.0f}});
    RenderScene scene = std::move(builder).build();
    ASSERT_EQ(scene.lods.count("city/box"), 1u);
    const LodCounts &facades = scene.lods.at("city/facades"), &boxes = scene.lods.at("city/box");
    // Lots whose middle lies within 300 m: x + 6 < √(300² − 27² − 2²) ≈ 298.8, the first 25.
    EXPECT_EQ(facades.buildings, 25u);
    EXPECT_EQ(boxes.buildings, 575u);
    EXPECT_EQ(boxes.meshes, 1u);
    EXPECT_EQ(boxes.instances, 0u);
    EXPECT_LT(boxes.triangles, 40 * boxes.buildings) << "a plain quad a wall and the roof";
    EXPECT_EQ(scene.buildings.size(), 600u) << "every building keeps its record";
}

// By default a building that spans fewer than 8 pixels of the image's height is a box: along
// the row those are the farthest, and a sharper image keeps more of them in full.
TEST(GenerateCity, BuildingsTooSmallInTheImageAreBoxes) {
    CityData data = rowOfLots({});
    auto withFacades = [&](int width, int height) {
        RenderSceneBuilder builder;
        std::vector<std::string> warnings;
        generateCity(data, 0, 1, builder, warnings, nullptr, {atTheWestEnd(width, height), CoarseRule{}});
        RenderScene scene = std::move(builder).build();
        uint64_t kept = scene.lods.at("city/facades").buildings;
        EXPECT_EQ(kept + scene.lods.at("city/box").buildings, 600u);
        float east = 0;
        for (const Instance &instance : scene.instances) east = std::max(east, instance.objectToWorld.m[3]);
        EXPECT_LT(east, 12.0f * float(kept) + 1) << "the buildings in full are the nearest";
        return kept;
    };
    uint64_t small = withFacades(640, 360), large = withFacades(2560, 1440);
    EXPECT_GT(small, 10u);
    EXPECT_LT(small, 300u);
    EXPECT_GT(large, small + small / 2);
}

TEST(GenerateCity, TheGeometryBudgetTakesFacadesFromTheFarthestBuildingsFirst) {
    CityData data = rowOfLots({});
    auto built = [&](uint64_t budget, std::vector<std::string> &warnings) {
        RenderSceneBuilder builder;
        builder.setGeometryBudget(budget);
        generateCity(data, 0, 1, builder, warnings, nullptr, {atTheWestEnd(), CoarseRule{std::nullopt, 0.0f}});
        return std::move(builder).build();
    };
    std::vector<std::string> none, some;
    RenderScene whole = built(UINT64_MAX, none);
    EXPECT_EQ(whole.lods.count("city/box"), 0u);
    RenderScene part = built(100'000'000, some);
    ASSERT_EQ(part.lods.count("city/box"), 1u);
    uint64_t kept = part.lods.at("city/facades").buildings;
    EXPECT_GT(kept, 50u);
    EXPECT_LT(kept, 500u);
    bool warned = false;
    for (const std::string &w : some) warned |= w.find("drawn as boxes") != std::string::npos;
    EXPECT_TRUE(warned);
    // The buildings that kept their facades are the nearest: every instance lies west of
    // where the boxes begin.
    float east = 0;
    for (const Instance &instance : part.instances) east = std::max(east, instance.objectToWorld.m[3]);
    EXPECT_LT(east, 12.0f * float(kept) + 1);
}

TEST(GenerateCity, ErrorsAreAtTheirPlace) {
    auto errorOf = [](const std::string &xml) { return test::inputErrorOf([&] { build(xml); }); };
    EXPECT_NE(errorOf("<scene version=\"1\"><city file=\"nowhere.xml\"/></scene>")
                  .find("test.xml:1:32: cannot read the city file"),
              std::string::npos);
    EXPECT_NE(errorOf("<scene version=\"1\"><city file=\"../cities/bilke-listing-2-1.xml\" colour=\"red\"/></scene>")
                  .find("test.xml:1:"),
              std::string::npos);
}

}  // namespace
}  // namespace veduta
