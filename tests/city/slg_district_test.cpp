// The <slg> element (docs/slg.md): a block or district planned from the urban-geography tables
// alone, its buildings at the level of detail their distance from the camera asks for, its
// mistakes named with their place, and the same scene from the same seed.
#include <gtest/gtest.h>

#include <array>
#include <set>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "assembly/build_scene.h"
#include "city/slg_buildings.h"
#include "input_error.h"
#include "scene/scene_hash.h"
#include "test_paths.h"

namespace veduta {
namespace {

RenderScene sceneWith(const std::string &camera, const std::string &slg) {
    std::string xml =
        fmt::format(R"(<scene version="1"><camera {} look_at="50 40 0" up="0 0 1"/>{}</scene>)", camera, slg);
    std::vector<std::string> warnings;
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), &warnings);
}

const char *kBlock = R"(<slg outline="0 0 100 0 102 80 -3 78" tables="../rules/slg/urban-geography.xml" seed="4"/>)";

size_t triangles(const RenderScene &scene) {
    size_t n = 0;
    for (const BakedMesh &baked : scene.meshes) n += baked.mesh.triangleCount();
    return n;
}

uint64_t buildings(const RenderScene &scene) {
    uint64_t n = 0;
    for (const auto &[level, counts] : scene.lods) n += counts.buildings;
    return n;
}

TEST(SlgElement, ABlockIsBuiltWithABuildingOnEveryLotItPlans) {
    RenderScene scene = sceneWith(R"(position="-400 -400 300")", kBlock);
    EXPECT_GE(buildings(scene), 20u);
    // All far away: boxes, merged into one mesh for the block.
    ASSERT_EQ(scene.lods.size(), 1u);
    EXPECT_EQ(scene.lods.begin()->first, "slg/box");
    EXPECT_EQ(scene.lods.begin()->second.meshes, 1u);
    EXPECT_EQ(scene.lods.begin()->second.merged, buildings(scene));
}

// <slg> elements built straight into a builder with a geometry budget; every building within
// `rooms` metres and at least `rooms_above_px` high asks for its rooms.
struct SlgBuilt {
    RenderScene scene;
    std::vector<std::string> warnings;
};

SlgBuilt slgWithin(uint64_t budget, const std::string &slg, Vec3f cameraAt, int imageHeight = 360) {
    SceneDescription d =
        readSceneText(fmt::format(R"(<scene version="1">{}</scene>)", slg), "test.xml", test::sourceFile("scenes"));
    Camera camera;
    camera.position = cameraAt;
    camera.height = imageHeight;
    camera.width = imageHeight * 16 / 9;
    RenderSceneBuilder builder;
    builder.setGeometryBudget(budget);
    std::vector<uint32_t> seeds;
    for (const SlgDesc &element : d.slg) seeds.push_back(*element.seed);
    SlgBuilt out;
    generateSlg(d.slg, seeds, camera, nullptr, builder, out.warnings);
    out.scene = std::move(builder).build();
    return out;
}

const char *kDistrict = R"(<slg level="district" outline="0 0 700 0 700 700 0 700" seed="3" )"
                        R"(tables="../rules/slg/urban-geography.xml" rooms_within="100000" storeys_within="100000" )"
                        R"(rooms_above_px="0" storeys_above_px="0"/>)";

TEST(SlgElement, ADistrictIsFilledRingByRingToItsMiddle) {
    SlgBuilt built = slgWithin(UINT64_MAX, kDistrict, {-50, -50, 30});
    // The first ring alone had about 170 buildings on this outline.
    EXPECT_GE(buildings(built.scene), 600u);
    bool middle = false;
    for (const BakedMesh &baked : built.scene.meshes)
        for (Vec3f p : baked.mesh.positions) middle |= p.z > 5 && std::abs(p.x - 350) < 60 && std::abs(p.y - 350) < 60;
    EXPECT_TRUE(middle) << "a building within 60 m of the district's middle";
}

TEST(SlgElement, TheGeometryBudgetTakesDetailFromTheFarthestBuildingsFirst) {
    SlgBuilt whole = slgWithin(UINT64_MAX, kDistrict, {-50, -50, 30});
    ASSERT_EQ(whole.scene.lods.count("slg/rooms"), 1u);
    uint64_t bytes = whole.scene.lods.at("slg/rooms").triangles * kBytesPerTriangle;
    EXPECT_TRUE(whole.warnings.empty() || whole.warnings[0].find("budget") == std::string::npos);

    // A building drawn storey by storey costs about a quarter of one with its rooms, so at half
    // the cost of all with rooms about a third of them keep their rooms.
    uint64_t budget = bytes / 2;
    SlgBuilt part = slgWithin(budget, kDistrict, {-50, -50, 30});
    ASSERT_FALSE(part.warnings.empty());
    EXPECT_NE(part.warnings[0].find("drawn coarser"), std::string::npos) << part.warnings[0];
    EXPECT_LE(triangles(part.scene) * kBytesPerTriangle, budget);
    EXPECT_EQ(buildings(part.scene), buildings(whole.scene));
    // Rooms are kept for the buildings nearest the camera: the farthest corner of any with
    // rooms is nearer than the middle of the district.
    float farthestRooms = 0;
    MaterialId interior = kNoMaterial;
    for (size_t m = 0; m < part.scene.materials.size(); ++m)
        if (part.scene.materials[m].name == "slg/interior") interior = MaterialId(m);
    for (const BakedMesh &baked : part.scene.meshes) {
        const Mesh &mesh = baked.mesh;
        if (std::find(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(), interior) ==
            mesh.triangleMaterials.end())
            continue;
        for (Vec3f p : mesh.positions) farthestRooms = std::max(farthestRooms, length(p - Vec3f{-50, -50, 30}));
    }
    EXPECT_GT(farthestRooms, 0);
    EXPECT_LT(farthestRooms, length(Vec3f{350, 350, 0} - Vec3f{-50, -50, 30}));
}

// Without distances, the levels follow the buildings' size in the image alone: a sharper image
// shows more of them storey by storey and with their rooms.
TEST(SlgElement, LevelsFollowTheSizeInTheImage) {
    const char *district = R"(<slg level="district" outline="0 0 700 0 700 700 0 700" seed="3" )"
                           R"(tables="../rules/slg/urban-geography.xml" rooms_within="100000" )"
                           R"(storeys_within="100000"/>)";
    auto levels = [&](int imageHeight) {
        SlgBuilt built = slgWithin(UINT64_MAX, district, {-50, -50, 30}, imageHeight);
        auto count = [&](const char *level) {
            auto it = built.scene.lods.find(level);
            return it == built.scene.lods.end() ? uint64_t(0) : it->second.buildings;
        };
        return std::array<uint64_t, 3>{count("slg/rooms"), count("slg/storeys"), count("slg/box")};
    };
    std::array<uint64_t, 3> small = levels(120), sharp = levels(1080);
    EXPECT_EQ(small[0] + small[1] + small[2], sharp[0] + sharp[1] + sharp[2]);
    EXPECT_GT(small[2], 0u) << "the farthest are boxes";
    EXPECT_GT(sharp[0], small[0]);
    EXPECT_GT(sharp[0] + sharp[1], small[0] + small[1]);
}

// Eq 1 for every built lot, summed by its BauNVO zone beside Table 2's caps (veduta info).
TEST(SlgElement, DensitiesAreReportedBesideTableTwo) {
    SlgBuilt built = slgWithin(UINT64_MAX, kDistrict, {-50, -50, 30});
    uint64_t lots = 0;
    for (const auto &[zone, d] : built.scene.densities) {
        SCOPED_TRACE(zone);
        lots += d.lots;
        EXPECT_GT(d.footprintArea / d.lotArea, 0.05);
        EXPECT_LT(d.footprintArea / d.lotArea, 1.0);
        EXPECT_GE(d.floorArea, d.footprintArea);
    }
    EXPECT_EQ(lots, buildings(built.scene)) << "every lot with a building has a zone";
    ASSERT_EQ(built.scene.densities.count("Wohngebiet"), 1u);
    EXPECT_EQ(built.scene.densities.at("Wohngebiet").grzCap, 0.4);  // Table 2
    EXPECT_EQ(built.scene.densities.at("Wohngebiet").gfzCap, 1.2);
}

// A district of four quarters, each filled on a thread of its own when there are two.
TEST(SlgElement, TheSameBitsOnAnyNumberOfThreads) {
    const char *large = R"(<slg level="district" outline="0 0 2100 0 2100 1900 0 1900" seed="3" )"
                        R"(tables="../rules/slg/urban-geography.xml" rooms_within="120" storeys_within="300"/>)";
    auto hashOn = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return sceneHash(slgWithin(UINT64_MAX, large, {-50, -50, 30}).scene);
    };
    EXPECT_EQ(hashOn(1), hashOn(2));
}

TEST(SlgElement, NearerCamerasSeeMoreDetail) {
    size_t far = triangles(sceneWith(R"(position="-400 -400 300")", kBlock));
    size_t near = triangles(sceneWith(R"(position="-10 -10 10")", kBlock));
    EXPECT_GT(near, 2 * far) << "storeys and rooms near the camera, boxes far away";
}

// A scene's material of an SLG material's name restyles every building's surfaces of it.
TEST(SlgElement, TheScenesMaterialsRestyleTheBuildings) {
    std::string slg = std::string(R"(<material name="slg/wall" diffuse="0.9 0.1 0.1"/>)") + kBlock;
    RenderScene scene = sceneWith(R"(position="-10 -10 10")", slg);
    MaterialId wall = kNoMaterial;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].name == "slg/wall") {
            EXPECT_EQ(wall, kNoMaterial) << "one slg/wall";
            wall = MaterialId(m);
            EXPECT_EQ(scene.materials[m].diffuse.x, 0.9f);
        }
    size_t walls = 0;
    for (const BakedMesh &baked : scene.meshes) walls += std::ranges::count(baked.mesh.triangleMaterials, wall);
    EXPECT_GT(walls, 100u);
}

TEST(SlgElement, TheSameSeedGivesTheSameSceneAndAnotherAnother) {
    std::string other = kBlock;
    other.replace(other.find("seed=\"4\""), 8, "seed=\"5\"");
    EXPECT_EQ(sceneHash(sceneWith(R"(position="-400 -400 300")", kBlock)),
              sceneHash(sceneWith(R"(position="-400 -400 300")", kBlock)));
    EXPECT_NE(sceneHash(sceneWith(R"(position="-400 -400 300")", kBlock)),
              sceneHash(sceneWith(R"(position="-400 -400 300")", other)));
}

TEST(SlgElement, MistakesAreNamedWithTheirPlace) {
    auto error = [](const std::string &slg) {
        return test::inputErrorOf([&] { sceneWith(R"(position="0 -100 50")", slg); });
    };
    EXPECT_EQ(error(R"(<slg outline="0 0 10 0" tables="../rules/slg/urban-geography.xml"/>)"),
              "test.xml:1:93: outline takes x y pairs of at least three corners");
    EXPECT_EQ(error(R"(<slg outline="0 0 10 10 10 0 0 10" tables="../rules/slg/urban-geography.xml"/>)"),
              "test.xml:1:93: the outline crosses itself");
    EXPECT_EQ(error(R"(<slg level="city" outline="0 0 10 0 5 5" tables="../rules/slg/urban-geography.xml"/>)"),
              "test.xml:1:91: level is 'block', 'district' or 'atkis', not 'city'");
    EXPECT_NE(error(R"(<slg outline="0 0 10 0 5 5" tables="missing.xml"/>)").find("missing.xml"), std::string::npos);
}

}  // namespace
}  // namespace veduta
