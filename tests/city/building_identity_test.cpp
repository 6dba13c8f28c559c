// A city building's identity comes from its source, never from a count of earlier things
// (issue 16): adding a lot or a block to a CityData file leaves every other building as it was.
#include <gtest/gtest.h>

#include <algorithm>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/building_pieces.h"
#include "test_paths.h"

namespace veduta {
namespace {

// Two blocks between streets: the west one cut into lots, the east one with lots of its own.
// Points 20 to 27 lie north of them, off every street, for a block added later.
constexpr const char *kPoints = R"(
    <Point id="0" e="0" n="0"/><Point id="1" e="60" n="0"/><Point id="2" e="60" n="60"/><Point id="3" e="0" n="60"/>
    <Point id="4" e="80" n="0"/><Point id="5" e="140" n="0"/><Point id="6" e="140" n="60"/><Point id="7" e="80" n="60"/>
    <Point id="10" e="80" n="14"/><Point id="11" e="100" n="0"/><Point id="12" e="100" n="14"/>
    <Point id="13" e="120" n="0"/><Point id="14" e="120" n="14"/><Point id="15" e="140" n="14"/>
    <Point id="20" e="0" n="100"/><Point id="21" e="60" n="100"/><Point id="22" e="60" n="160"/><Point id="23" e="0" n="160"/>
    <Point id="24" e="20" n="100"/><Point id="25" e="20" n="114"/><Point id="26" e="0" n="114"/>)";

constexpr const char *kStreets = R"(
    <Street id="0" startPoint="0" endPoint="1"/><Street id="1" startPoint="1" endPoint="2"/>
    <Street id="2" startPoint="2" endPoint="3"/><Street id="3" startPoint="3" endPoint="0"/>
    <Street id="4" startPoint="4" endPoint="5"/><Street id="5" startPoint="5" endPoint="6"/>)";

constexpr const char *kCutBlock = R"(<Block><Points>
    <Point id="0"/><Point id="1"/><Point id="2"/><Point id="3"/></Points></Block>)";

// A lot on the south street of the east block, from point a to b, back through c and d.
std::string lot(int a, int b, int c, int d) {
    return fmt::format(R"(<Lot><Points><Point id="{}" streetEdge="1"/><Point id="{}"/><Point id="{}"/><Point id="{}"/>
        </Points></Lot>)",
                       a, b, c, d);
}

std::string ownLotsBlock(const std::string &lots) {
    return R"(<Block><Points><Point id="4"/><Point id="5"/><Point id="6"/><Point id="7"/></Points><Lots>)" + lots +
        "</Lots></Block>";
}

// A block north of the others, off the streets, with one lot of its own.
constexpr const char *kNorthBlock = R"(<Block><Points>
    <Point id="20"/><Point id="21"/><Point id="22"/><Point id="23"/></Points><Lots>
    <Lot><Points><Point id="20" streetEdge="1"/><Point id="24"/><Point id="25"/><Point id="26"/></Points></Lot>
    </Lots></Block>)";

class BuildingIdentity : public testing::Test {
  protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() / fmt::format("veduta_building_identity_{}", ::getpid());
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }

    // The buildings of a scene whose <city> reads a CityData file of these blocks.
    std::map<uint32_t, std::vector<test::Piece>> cityOf(const std::string &blocks) {
        std::filesystem::path file = folder_ / "city.xml";
        std::ofstream(file) << fmt::format(R"(<CityData><Points>{}</Points>
            <StreetNetwork><Streets>{}</Streets><Width>6</Width></StreetNetwork>
            <Blocks>{}</Blocks>
            <BuildingSettings><BuildingHeight>14</BuildingHeight><BuildingHeightVar>3</BuildingHeightVar>
            <MinBuildingDepth>10</MinBuildingDepth></BuildingSettings></CityData>)",
                                           kPoints, kStreets, blocks);
        std::string scene = fmt::format(R"(<scene version="1"><city file="{}" rules="{}" seed="4"/></scene>)",
                                        file.string(), test::sourceFile("rules/gruenderzeit/FacadeStructure.xml"));
        return test::buildingsOf(buildRenderScene(readSceneText(scene, "test.xml", folder_)));
    }

    static size_t partyWallTriangles(const std::vector<test::Piece> &pieces) {
        size_t count = 0;
        for (const test::Piece &p : pieces)
            count += size_t(std::count(p.materials.begin(), p.materials.end(), "party_wall"));
        return count;
    }

    // Every building of `before` is in `after`, under its id and bit for bit, except
    // `partyWalls` of them: those the new lot's building stands against, which gain a party wall
    // (party_walls.h) where they had a facade.
    static void expectKept(const std::map<uint32_t, std::vector<test::Piece>> &before,
                           const std::map<uint32_t, std::vector<test::Piece>> &after, size_t partyWalls = 0) {
        size_t walled = 0;
        for (const auto &[id, pieces] : before) {
            auto it = after.find(id);
            if (it == after.end()) {
                ADD_FAILURE() << "building " << id << " is gone";
            } else if (!(it->second == pieces)) {
                EXPECT_GT(partyWallTriangles(it->second), partyWallTriangles(pieces))
                    << "building " << id << " changed";
                ++walled;
            }
        }
        EXPECT_EQ(walled, partyWalls);
    }

    std::filesystem::path folder_;
};

TEST_F(BuildingIdentity, AnotherLotOfItsBlockLeavesEveryBuildingAsItWas) {
    std::string lots = lot(11, 13, 14, 12) + lot(13, 5, 15, 14);
    auto before = cityOf(std::string(kCutBlock) + ownLotsBlock(lots));
    auto after = cityOf(std::string(kCutBlock) + ownLotsBlock(lot(4, 11, 12, 10) + lots));
    ASSERT_GE(before.size(), 4u);  // the cut block's lots and the two given ones
    EXPECT_EQ(after.size(), before.size() + 1);
    expectKept(before, after, 1);  // the new lot shares its edge 11–12 with the lot 11, 13, 14, 12
}

TEST_F(BuildingIdentity, ABlockAddedBeforeACutBlockLeavesItsLotsAsTheyWere) {
    std::string rest = std::string(kCutBlock) + ownLotsBlock(lot(4, 11, 12, 10));
    auto before = cityOf(rest);
    auto after = cityOf(kNorthBlock + rest);
    ASSERT_GE(before.size(), 3u);
    EXPECT_EQ(after.size(), before.size() + 1);
    expectKept(before, after);
}

}  // namespace
}  // namespace veduta
