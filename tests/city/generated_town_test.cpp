// <generate> in scene files: a town grown from street rules and built as a <city> is.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

#include <fmt/format.h>

#include <tbb/global_control.h>

#include "assembly/build_scene.h"
#include "input_error.h"
#include "scene/scene_hash.h"
#include "test_paths.h"

namespace veduta {
namespace {

RenderScene build(const std::string &xml, std::vector<std::string> *warnings = nullptr) {
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), warnings);
}

std::string scene(const std::string &generate, const std::string &before = "") {
    return fmt::format(
        "<scene version=\"1\">{}<generate streets=\"../rules/streets/grid.txt\" "
        "rules=\"../rules/gruenderzeit/FacadeStructure.xml\" {}/></scene>",
        before, generate);
}

// The middle of the street meshes' box, in metres of the scene frame.
Vec2f streetsMiddle(const RenderScene &built) {
    float lo[2] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    float hi[2] = {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest()};
    for (const BakedMesh &m : built.meshes)
        if (m.buildingId == 0)
            for (const Vec3f &p : m.mesh.positions) {
                lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
                lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
            }
    return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
}

TEST(GeneratedTown, GrowsStreetsAndBuildsItsLots) {
    std::vector<std::string> warnings;
    RenderScene built = build(scene("radius=\"200\" seed=\"3\""), &warnings);
    std::set<uint32_t> buildings;
    for (const BakedMesh &m : built.meshes) buildings.insert(m.buildingId);
    EXPECT_TRUE(buildings.count(0));  // the streets
    EXPECT_GT(buildings.size(), 20u);
    RenderScene again = build(scene("radius=\"200\" seed=\"3\""));
    ASSERT_EQ(again.meshes.size(), built.meshes.size());
    for (size_t i = 0; i < built.meshes.size(); ++i)
        EXPECT_EQ(again.meshes[i].mesh.positions, built.meshes[i].mesh.positions) << i;
}

// Lots are cut and buildings made on all cores, and added in one order: the scene is the same
// for any number of threads, down to its hash.
TEST(GeneratedTown, IsTheSameOnAnyNumberOfThreads) {
    auto builtOn = [](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return build(scene("radius=\"250\" seed=\"11\" lots=\"schrader\""));
    };
    RenderScene one = builtOn(1), four = builtOn(4);
    EXPECT_GT(one.buildings.size(), 20u);
    EXPECT_EQ(one.meshes.size(), four.meshes.size());
    EXPECT_EQ(one.instances.size(), four.instances.size());
    EXPECT_EQ(one.prototypes.size(), four.prototypes.size());
    EXPECT_EQ(sceneHash(one), sceneHash(four));
}

std::string tensorScene(const std::string &attributes) {
    return fmt::format(
        "<scene version=\"1\"><generate {} rules=\"../rules/gruenderzeit/FacadeStructure.xml\"/></scene>", attributes);
}

// pattern="tensor": streets traced through the seeded field, built as any grown town.
TEST(GeneratedTown, ATensorFieldTownIsBuiltAsAnyOther) {
    RenderScene built = build(tensorScene("pattern=\"tensor\" radius=\"250\" seed=\"8\""));
    EXPECT_GT(built.buildings.size(), 40u);
    EXPECT_EQ(sceneHash(built), sceneHash(build(tensorScene("pattern=\"tensor\" radius=\"250\" seed=\"8\""))));
    EXPECT_NE(sceneHash(built), sceneHash(build(tensorScene("pattern=\"tensor\" radius=\"250\" seed=\"9\""))));
    EXPECT_EQ(
        test::inputErrorOf([] { build(tensorScene("pattern=\"tensor\" streets=\"../rules/streets/grid.txt\"")); }),
        "test.xml:1:39: give either streets (a rule file) or pattern, not both");
    EXPECT_EQ(test::inputErrorOf([] { build(tensorScene("pattern=\"voronoi\"")); }),
              "test.xml:1:39: unknown pattern 'voronoi'; the one pattern without a rule file is tensor");
}

// roads="…osm": the highways of an OpenStreetMap file are streets the town grows onto.
TEST(GeneratedTown, GrowsOntoTheRoadsOfAnOpenStreetMapFile) {
    const char *georeference = "<georeference crs=\"EPSG:25832\" origin=\"500000 5330150\"/>";
    RenderScene free = build(scene("radius=\"200\" seed=\"4\" centre=\"500000 5330150\"", georeference));
    RenderScene onRoads = build(
        scene("radius=\"200\" seed=\"4\" centre=\"500000 5330150\" roads=\"../data/hillside/town.osm\"", georeference));
    EXPECT_GT(onRoads.buildings.size(), 0u);
    EXPECT_NE(sceneHash(free), sceneHash(onRoads));
    EXPECT_EQ(test::inputErrorOf([] { build(scene("roads=\"../data/hillside/town.osm\"")); }),
              "test.xml:1:123: roads from OpenStreetMap need the scene's <georeference> to be placed");
}

TEST(GeneratedTown, LiesAtItsCentreInTheScenesCrs) {
    RenderScene local = build(scene("radius=\"150\" centre=\"400 -300\""));
    Vec2f middle = streetsMiddle(local);
    // The grid is nearly symmetric about its origin: the middle lies within a block of it.
    EXPECT_NEAR(middle.x, 400, 80);
    EXPECT_NEAR(middle.y, -300, 80);
    RenderScene mapped = build(scene("radius=\"150\" centre=\"487400 5424700\"",
                                     "<georeference crs=\"EPSG:25832\" origin=\"487000 5425000\"/>"));
    Vec2f placed = streetsMiddle(mapped);
    EXPECT_NEAR(placed.x, middle.x, 0.01);
    EXPECT_NEAR(placed.y, middle.y, 0.01);
}

TEST(GeneratedTown, ErrorsAreAtTheirPlace) {
    auto errorOf = [](const std::string &xml) { return test::inputErrorOf([&] { build(xml); }); };
    std::string missing = errorOf(
        "<scene version=\"1\"><generate streets=\"nowhere.txt\" rules=\"../rules/gruenderzeit/FacadeStructure.xml\"/>"
        "</scene>");
    EXPECT_NE(missing.find("test.xml:1:39: cannot read the street rule file"), std::string::npos) << missing;
    std::string grade = errorOf(scene("max_grade=\"3\""));
    EXPECT_NE(grade.find("max_grade"), std::string::npos) << grade;
    std::string centre = errorOf(scene("centre=\"1 2 3\""));
    EXPECT_NE(centre.find("centre takes two numbers"), std::string::npos) << centre;
    std::string far = errorOf(scene("centre=\"487400 5424700\""));
    EXPECT_NE(far.find("more than 100 km from the scene origin; map coordinates need a <georeference>"),
              std::string::npos)
        << far;
    // Checked at once, before any block needs it: a window of no block is still refused.
    std::string lots = errorOf(scene("radius=\"30\" lots=\"hexagons\""));
    EXPECT_NE(lots.find("hexagons"), std::string::npos) << lots;
    EXPECT_NE(lots.find("test.xml:1:"), std::string::npos) << lots;
}

}  // namespace
}  // namespace veduta
