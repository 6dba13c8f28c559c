// <scene seed> reaches every random choice (issue 16): the sampler's and every generator's
// (buildings, roofs, palette, city lots), unless the element gives a seed of its own, which
// then restores what it drew before. Trees: tests/geo/generate_landscape_test.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/building_pieces.h"
#include "render/sampler.h"
#include "scene/scene_hash.h"
#include "test_paths.h"

namespace veduta {
namespace {

const std::string kRules = test::sourceFile("rules/gruenderzeit/FacadeStructure.xml");

// Scene XML with `seed` on <scene> and `own` (an attribute or nothing) where the body says {own}.
std::string sceneXml(uint32_t seed, const std::string &own, const std::string &body) {
    return fmt::format("<scene version=\"1\" seed=\"{}\">{}</scene>", seed,
                       fmt::format(fmt::runtime(body), fmt::arg("own", own)));
}

RenderScene build(uint32_t seed, const std::string &own, const std::string &body) {
    return buildRenderScene(readSceneText(sceneXml(seed, own, body), "test.xml", test::sourceFile("scenes")));
}

// What one generator drew, as `extract` sees it, differs between scene seeds 0 and 5, and the
// element's own seed="0" under scene seed 5 gives what scene seed 0 gave.
template <typename Extract>
void expectSceneSeedReaches(const std::string &body, Extract extract) {
    auto atZero = extract(build(0, "", body));
    EXPECT_NE(extract(build(5, "", body)), atZero) << "scene seed 5 drew as 0 did";
    EXPECT_EQ(extract(build(5, "seed=\"0\"", body)), atZero) << "the element's own seed did not override";
}

// Four houses in a row, each facing the street at y = 0.
std::string houses(const std::string &settings) {
    std::string body =
        fmt::format("<buildings rules=\"{}\" {{own}}><BuildingSettings>{}</BuildingSettings>", kRules, settings);
    for (int i = 0; i < 4; ++i) {
        body += fmt::format("<building footprint=\"{0} 0 {1} 0 {1} 12 {0} 12\" street=\"0\"/>", 20 * i, 20 * i + 14);
    }
    return body + "</buildings>";
}

// Per building: the highest point of it.
std::map<uint32_t, float> tops(const RenderScene &scene) {
    std::map<uint32_t, float> top;
    for (const auto &[id, pieces] : test::buildingsOf(scene)) {
        float z = -1e30f;
        for (const test::Piece &piece : pieces) {
            for (size_t i = 2; i < piece.positions.size(); i += 3) z = std::max(z, piece.positions[i]);
        }
        top[id] = z;
    }
    return top;
}

TEST(SceneSeed, ReachesTheSamplerUnlessRenderGivesASeed) {
    const std::string body = "<render {own}/><sphere radius=\"1\"/>";
    EXPECT_EQ(build(5, "", body).settings.seed, 5u);
    EXPECT_EQ(build(5, "seed=\"0\"", body).settings.seed, 0u);
    PixelSampler zero(0, 3, 4, 0), five(5, 3, 4, 0);
    std::array<Vec2f, 4> a, b;
    for (size_t d = 0; d < a.size(); ++d) a[d] = zero.next2D(), b[d] = five.next2D();
    EXPECT_FALSE(std::equal(a.begin(), a.end(), b.begin(), [](Vec2f p, Vec2f q) { return p.x == q.x && p.y == q.y; }));
}

TEST(SceneSeed, ReachesTheBuildingHeights) {
    expectSceneSeedReaches(houses("<BuildingHeight>15</BuildingHeight><BuildingHeightVar>4</BuildingHeightVar>"), tops);
}

TEST(SceneSeed, ReachesTheRoofChoice) {
    // One roof material, fixed heights: only the roof type drawn from the list changes the roofs.
    std::string body = "<material name=\"tiles\" category=\"roof\"/>" +
        houses("<BuildingHeightVar>0</BuildingHeightVar><RoofHeightVar>0</RoofHeightVar>"
               "<RoofType>flat gable hip mansard pyramid shed</RoofType>");
    expectSceneSeedReaches(body, [](const RenderScene &scene) {
        std::vector<std::vector<float>> roofs;
        for (const auto &[id, pieces] : test::buildingsOf(scene)) {
            std::vector<float> &roof = roofs.emplace_back();
            for (const test::Piece &piece : pieces) {
                for (size_t t = 0; t < piece.materials.size(); ++t) {
                    if (piece.materials[t] != "tiles") continue;
                    for (size_t k = 0; k < 3; ++k) {
                        auto corner = piece.positions.begin() + 3 * piece.indices[3 * t + k];
                        roof.insert(roof.end(), corner, corner + 3);
                    }
                }
            }
        }
        return roofs;
    });
}

TEST(SceneSeed, ReachesTheMaterialPalette) {
    std::string materials;
    for (const char *category : {"facade", "wall", "window", "door", "material", "roof"})
        for (int k = 0; k < 4; ++k)
            materials += fmt::format("<material name=\"{0}{1}\" category=\"{0}\"/>", category, k);
    expectSceneSeedReaches(materials + houses(""), [](const RenderScene &scene) {
        std::map<uint32_t, std::set<std::string>> used;
        for (const auto &[id, pieces] : test::buildingsOf(scene))
            for (const test::Piece &piece : pieces) used[id].insert(piece.materials.begin(), piece.materials.end());
        return used;
    });
}

// The city's lots (a block cut by the subdivision) and its buildings.
TEST(SceneSeed, ReachesTheCityLotsAndBuildings) {
    std::filesystem::path file =
        std::filesystem::temp_directory_path() / fmt::format("veduta_scene_seed_{}.xml", ::getpid());
    std::ofstream(file) << R"(<CityData><Points>
        <Point id="0" e="0" n="0"/><Point id="1" e="80" n="0"/><Point id="2" e="80" n="60"/><Point id="3" e="0" n="60"/>
        </Points><StreetNetwork><Streets><Street id="0" startPoint="0" endPoint="1"/>
        <Street id="1" startPoint="1" endPoint="2"/></Streets><Width>6</Width></StreetNetwork>
        <Blocks><Block><Points><Point id="0"/><Point id="1"/><Point id="2"/><Point id="3"/></Points></Block></Blocks>
        </CityData>)";
    std::string body = fmt::format("<city file=\"{}\" rules=\"{}\" {{own}}/>", file.string(), kRules);
    // The lots alone: where each building stands, whatever its facades.
    expectSceneSeedReaches(body, [](const RenderScene &scene) {
        std::multiset<std::array<float, 4>> extents;
        for (const auto &[id, pieces] : test::buildingsOf(scene)) {
            std::array<float, 4> box{1e30f, 1e30f, -1e30f, -1e30f};
            for (const test::Piece &piece : pieces) {
                for (size_t i = 0; i + 2 < piece.positions.size(); i += 3) {
                    box = {std::min(box[0], piece.positions[i]), std::min(box[1], piece.positions[i + 1]),
                           std::max(box[2], piece.positions[i]), std::max(box[3], piece.positions[i + 1])};
                }
            }
            extents.insert(box);
        }
        return extents;
    });
    expectSceneSeedReaches(body, test::buildingsOf);
    // The sampler's seed stays 0 in all three: the scene hash follows the city's seed anyway.
    std::string pinned = "<render seed=\"0\"/>" + body;
    EXPECT_NE(sceneHash(build(0, "", pinned)), sceneHash(build(5, "", pinned)));
    EXPECT_EQ(sceneHash(build(0, "", pinned)), sceneHash(build(5, "seed=\"0\"", pinned)));
    std::filesystem::remove(file);
}

// --seed: every seed of the file gives way to it.
TEST(SceneSeed, TheCommandLineSeedReplacesEveryOther) {
    std::string body =
        "<render seed=\"7\"/><buildings rules=\"r.xml\" seed=\"1\"/><city file=\"c.xml\" seed=\"2\"/>"
        "<landscape seed=\"3\"><dgm file=\"d.asc\"/></landscape>";
    SceneDescription d = readSceneText(sceneXml(9, "", body), "test.xml", ".");
    replaceEverySeed(d, 5);
    EXPECT_EQ(d.seed, 5u);
    EXPECT_FALSE(d.renderSeed);
    EXPECT_FALSE(d.buildingGroups.at(0).seed);
    EXPECT_FALSE(d.cities.at(0).seed);
    EXPECT_FALSE(d.landscape->seed);
}

}  // namespace
}  // namespace veduta
