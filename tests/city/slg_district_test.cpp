// The <slg> element (docs/slg.md): a block or district planned from the urban-geography tables
// alone, its buildings at the level of detail their distance from the camera asks for, its
// mistakes named with their place, and the same scene from the same seed.
#include <gtest/gtest.h>

#include <set>

#include <fmt/format.h>

#include "assembly/build_scene.h"
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

TEST(SlgElement, ABlockIsBuiltWithABuildingOnEveryLotItPlans) {
    RenderScene scene = sceneWith(R"(position="-400 -400 300")", kBlock);
    std::set<uint32_t> buildings;
    for (const BakedMesh &baked : scene.meshes)
        if (baked.buildingId != 0) buildings.insert(baked.buildingId);
    EXPECT_GE(buildings.size(), 20u);
}

TEST(SlgElement, NearerCamerasSeeMoreDetail) {
    size_t far = triangles(sceneWith(R"(position="-400 -400 300")", kBlock));
    size_t near = triangles(sceneWith(R"(position="-10 -10 10")", kBlock));
    EXPECT_GT(near, 2 * far) << "storeys and rooms near the camera, boxes far away";
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
              "test.xml:1:91: level is 'block' or 'district', not 'city'");
    EXPECT_NE(error(R"(<slg outline="0 0 10 0 5 5" tables="missing.xml"/>)").find("missing.xml"), std::string::npos);
}

}  // namespace
}  // namespace veduta
