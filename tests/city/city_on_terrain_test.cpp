// A <city> on a <landscape>: its streets cut into the terrain above the ATKIS areas (no forest
// and no tree on them), its buildings seated on the terrain with a plinth, and without a
// landscape its streets exactly the flat plan. The city is made in memory in the local frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <unistd.h>

#include "assembly/build_scene.h"
#include "city/generate_city.h"
#include "city/plinth.h"
#include "city/streets_on_terrain.h"
#include "city/terrain_checks.h"
#include "description/scene_description.h"
#include "esri_ascii_grid.h"
#include "geo/generate_landscape.h"
#include "test_paths.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

using test::materialNamed;
using test::Seat;
using test::seats;

constexpr double kWest = 530000, kSouth = 5326000, kSpacing = 10;
constexpr int kNodes = 21;

// A hillside rising 9 % to the east and 12 % to the north, with a bump.
double height(int c, int r) { return 400 + 0.9 * c + 1.2 * r + ((c * 7 + r * 3) % 5) * 0.3; }

// A main street along y = 0 and one up the hill at x = 20 (local metres), two lots on the
// main street's north side.
CityData town() {
    CityData data;
    for (auto [e, n] :
         std::initializer_list<std::pair<double, double>>{{-95, 0}, {20, 0}, {95, 0}, {20, 95}, {20, -95}})
        data.points.push_back({uint32_t(data.points.size()), e, n, 0, {}});
    data.streets = {{0, 0, 1, 8.0f, {}}, {1, 1, 2, 8.0f, {}}, {2, 1, 3, 6.0f, {}}, {3, 1, 4, 6.0f, {}}};
    CityBlock block;
    block.points = {{-95, 0}, {20, 0}, {20, 95}, {-95, 95}};
    for (float x : {-40.0f, -20.0f}) {
        CityLot lot;
        lot.points = {{x, 6.5f}, {x + 20, 6.5f}, {x + 20, 26.5f}, {x, 26.5f}};
        lot.streetEdges = {true, false, false, false};
        lot.sourceId = uint32_t(block.lots.size() + 1);  // as a file's lots have, from their points
        block.lots.push_back(lot);
    }
    data.blocks.push_back(block);
    data.ruleFiles.push_back(test::sourceFile("rules/gruenderzeit/FacadeStructure.xml"));
    return data;
}

bool inStreets(const std::vector<LocalPolygon> &pieces, Vec2d p) {
    for (const LocalPolygon &piece : pieces) {  // each convex, counter-clockwise
        bool inside = true;
        for (size_t i = 0; i < piece.size() && inside; ++i) {
            Vec2d a = piece[i], b = piece[(i + 1) % piece.size()];
            inside = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) > 1e-9;
        }
        if (inside) return true;
    }
    return false;
}

class CityOnTerrain : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
            fmt::format("veduta_city_terrain_{}_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(),
                        getpid());
        fs::create_directories(dir_);
        std::ofstream(dir_ / "dgm.asc") << test::esriAsciiGrid(
            kNodes, kNodes, kWest, kSouth, kSpacing, [](int c, int r) { return fmt::format("{:.3f}", height(c, r)); });
        // A forest over the north half and a meadow over the south, both across the streets.
        std::ofstream(dir_ / "areas.geojson") << R"({"type": "FeatureCollection",
 "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::25832"}},
 "features": [
  {"type": "Feature", "properties": {"OBJART": 4107, "OBJID": "F1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530000, 5326090], [530200, 5326090], [530200, 5326200], [530000, 5326200], [530000, 5326090]]]}},
  {"type": "Feature", "properties": {"OBJART": 4102, "OBJID": "M1"},
   "geometry": {"type": "Polygon", "coordinates": [[[530000, 5326000], [530200, 5326000], [530200, 5326095], [530000, 5326095], [530000, 5326000]]]}}
 ]})";
        description_ = readSceneText(
            "<scene version=\"1\">\n<georeference crs=\"EPSG:25832\" origin=\"530100 5326100\"/>\n"
            "<landscape seed=\"4\"><dgm file=\"dgm.asc\"/><atkis file=\"areas.geojson\"/></landscape>\n"
            "</scene>\n",
            "test.xml", dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    LandscapeGround landscape(const std::vector<LocalPolygon> &streets, RenderSceneBuilder &builder) {
        std::vector<std::string> warnings;
        return generateLandscape(*description_.landscape, 0, description_.georeference, streets, builder, warnings);
    }

    fs::path dir_;
    SceneDescription description_;
};

struct Intrusions {
    size_t forestTriangles = 0, meadowTriangles = 0, trees = 0, streetTriangles = 0;
};

Intrusions intoStreets(const RenderScene &s, const std::vector<LocalPolygon> &streets) {
    Intrusions found;
    const Mesh &terrain = s.meshes[0].mesh;
    MaterialId forest = materialNamed(s, "land/forest"), meadow = materialNamed(s, "land/grassland");
    MaterialId street = materialNamed(s, "land/city_street");
    for (size_t t = 0; t < terrain.triangleCount(); ++t) {
        Vec2d centre{};
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = terrain.positions[terrain.indices[3 * t + size_t(k)]];
            centre = {centre.x + p.x / 3, centre.y + p.y / 3};
        }
        if (!inStreets(streets, centre)) continue;
        MaterialId m = terrain.triangleMaterials[t];
        found.forestTriangles += m == forest, found.meadowTriangles += m == meadow,
            found.streetTriangles += m == street;
    }
    for (const Instance &tree : s.instances)
        found.trees += inStreets(streets, {tree.objectToWorld.m[3], tree.objectToWorld.m[7]});
    return found;
}

TEST_F(CityOnTerrain, StreetsWinOverTheAtkisAreasAndTreesKeepOff) {
    std::vector<LocalPolygon> streets = streetAreaPieces(streetNetworkOf(town()));
    RenderSceneBuilder builder;
    landscape(streets, builder);
    RenderScene s = std::move(builder).build();
    Intrusions found = intoStreets(s, streets);
    EXPECT_EQ(found.forestTriangles, 0u);
    EXPECT_EQ(found.meadowTriangles, 0u);
    EXPECT_EQ(found.trees, 0u);
    EXPECT_GT(found.streetTriangles, 100u);
    EXPECT_GT(s.instances.size(), 100u);  // the forest is there, off the streets

    // Without the streets cut in, the forest and the meadow run under them, trees on them.
    RenderSceneBuilder plain;
    landscape({}, plain);
    Intrusions under = intoStreets(std::move(plain).build(), streets);
    EXPECT_GT(under.forestTriangles, 100u);
    EXPECT_GT(under.meadowTriangles, 10u);
    EXPECT_GT(under.trees, 5u);
}

TEST_F(CityOnTerrain, BuildingsStandOnTheLowestTerrainUnderThemWithAPlinth) {
    CityData data = town();
    RenderSceneBuilder builder;
    LandscapeGround ground = landscape(streetAreaPieces(streetNetworkOf(data)), builder);
    std::vector<std::string> warnings;
    ASSERT_EQ(generateCity(data, 3, 1, builder, warnings, &ground), 2u);
    RenderScene s = std::move(builder).build();
    std::map<uint32_t, Seat> built = seats(s);
    ASSERT_EQ(built.size(), 2u);
    for (const CityLot &lot : data.blocks[0].lots) {
        uint32_t id = cityBuildingId(1, lot.sourceId);
        ASSERT_TRUE(built.count(id)) << id;
        double lowest = *ground.surface->minOver(lot.points);
        EXPECT_LE(built[id].walls - lowest, kPlinthDepth) << id;
        EXPECT_GE(built[id].walls - lowest, -1e-3) << id;  // not sunk either: the base is that lowest point
        EXPECT_LE(built[id].plinth, lowest) << id;
    }
    // The streets of the same city lie on the terrain.
    for (const BakedMesh &m : s.meshes) {
        if (m.buildingId != 0 || m.objectId != 1) continue;
        for (const Vec3f &p : m.mesh.positions) {
            if (std::optional<double> h = ground.surface->heightAt({p.x, p.y})) {
                EXPECT_GE(double(p.z), *h);
            }
        }
    }

    // Built flat at a CityData height above the hill instead, they float.
    CityData flat = town();
    for (CityLot &lot : flat.blocks[0].lots) lot.base = 440;
    RenderSceneBuilder floating;
    generateCity(flat, 3, 1, floating, warnings);
    std::map<uint32_t, Seat> up = seats(std::move(floating).build());
    uint32_t first = cityBuildingId(1, flat.blocks[0].lots[0].sourceId);
    ASSERT_TRUE(up.count(first));
    EXPECT_GT(up[first].walls - *ground.surface->minOver(flat.blocks[0].lots[0].points), kPlinthDepth);
}

TEST_F(CityOnTerrain, TheTerrainDecidesAndSaysSoWhenThePointsHaveHeights) {
    CityData data = town();
    data.points[2].u = 12;
    RenderSceneBuilder builder;
    LandscapeGround ground = landscape({}, builder);
    std::vector<std::string> warnings;
    generateCity(data, 3, 1, builder, warnings, &ground);
    size_t said = 0;
    for (const std::string &w : warnings)
        said += w.find("the heights u of its points (point 2: 12) are ignored") != std::string::npos;
    EXPECT_EQ(said, 1u);
    // Flat at u = 0, nothing to say.
    std::vector<std::string> none;
    RenderSceneBuilder again;
    generateCity(town(), 3, 1, again, none, &ground);
    for (const std::string &w : none) EXPECT_EQ(w.find("are ignored"), std::string::npos) << w;
}

// The acceptance test: the OSM extract and the DGM of scenes/hillside-town.xml (written by
// data/hillside/make_hillside.py) render with the streets on the terrain and the houses on it.
TEST(HillsideTown, StreetsLieOnTheTerrainAndHousesOnTheLowestGroundUnderThem) {
    std::vector<std::string> warnings;
    RenderScene s = buildRenderScene(readSceneFile(test::sourceFile("scenes/hillside-town.xml")), &warnings);
    const Mesh *terrain = nullptr;
    Mesh streets;
    MaterialId bare = materialNamed(s, "land/bare"), asphalt = materialNamed(s, "street/asphalt");
    for (const BakedMesh &m : s.meshes) {
        if (m.mesh.triangleCount() == 0) continue;
        const std::vector<MaterialId> &materials = m.mesh.triangleMaterials;
        if (!terrain && std::count(materials.begin(), materials.end(), bare) > 0) terrain = &m.mesh;
        if (std::count(materials.begin(), materials.end(), asphalt) > 0) streets.append(m.mesh, Transform());
    }
    ASSERT_TRUE(terrain);
    TerrainSurface surface(*terrain, {});
    ASSERT_GT(streets.triangleCount(), 1000u);
    EXPECT_EQ(test::pointsBelow(streets, surface), 0u);
    // The streets climb with the hill: the main street's nodes are 17 m below the top lane's.
    float low = 1e9f, high = -1e9f;
    for (const Vec3f &p : streets.positions) low = std::min(low, p.z), high = std::max(high, p.z);
    EXPECT_GT(high - low, 15.0f);

    // Each house's walls start on the lowest terrain under it, its plinth reaches below.
    size_t houses = 0;
    std::map<uint32_t, test::Seat> seated = seats(s);
    for (const BakedMesh &m : s.meshes) {
        if (m.buildingId == 0 || m.mesh.triangleMaterials.empty() ||
            m.mesh.triangleMaterials[0] != materialNamed(s, "plinth"))
            continue;
        std::vector<Vec2f> footprint;  // the plinth's top ring: the first vertex of each of its quads
        for (size_t v = 0; v < m.mesh.positions.size(); v += 4)
            footprint.push_back({m.mesh.positions[v].x, m.mesh.positions[v].y});
        double lowest = *surface.minOver(footprint);
        const test::Seat &seat = seated[m.buildingId];
        EXPECT_LE(seat.walls - lowest, kPlinthDepth) << m.buildingId;
        EXPECT_GE(seat.walls - lowest, -1e-3) << m.buildingId;
        EXPECT_LE(seat.plinth, lowest + 1e-3) << m.buildingId;
        ++houses;
    }
    EXPECT_GE(houses, 12u);  // the twelve houses and the perimeter lots of the other block
}

TEST(CityStreets, WithoutALandscapeTheyAreTheFlatPlan) {
    CityData data = town();
    RenderSceneBuilder builder;
    std::vector<std::string> warnings;
    generateCity(data, 3, 1, builder, warnings);
    RenderScene s = std::move(builder).build();
    Mesh plan = streetGeometry(streetNetworkOf(data));
    const BakedMesh *streets = nullptr;
    for (const BakedMesh &m : s.meshes)
        if (m.buildingId == 0) streets = &m;
    ASSERT_TRUE(streets);
    EXPECT_EQ(streets->mesh.positions, plan.positions);
    EXPECT_EQ(streets->mesh.indices, plan.indices);
    EXPECT_EQ(streets->mesh.normals, plan.normals);
}

}  // namespace
}  // namespace veduta
