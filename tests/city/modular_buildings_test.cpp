// <modular_building> in scene files: Finkenzeller's palace from its structure and style files,
// its masonry baked into an atlas the walls show.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "assembly/build_scene.h"
#include "city/modular_buildings.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

RenderScene build(const std::string &element, std::vector<std::string> *warnings = nullptr) {
    std::string xml = R"(<scene version="1"><camera position="60 -40 5" look_at="14 8 12" resolution="320 180"/>
        <materials file="../materials/palace.xml"/>)" +
        element + "</scene>";
    return buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")), warnings);
}

const Material *findMaterial(const RenderScene &scene, const std::string &part) {
    for (const Material &m : scene.materials)
        if (m.name.find(part) != std::string::npos) return &m;
    return nullptr;
}

TEST(ModularBuildings, ThePalaceInBrickShowsItsBakedMasonry) {
    std::vector<std::string> warnings;
    RenderScene scene =
        build(R"(<modular_building structure="palace/palace.structure" style="palace/brick.style" building="7"/>)",
              &warnings);
    ASSERT_EQ(scene.buildings.size(), 1u);
    EXPECT_EQ(scene.buildings[0].id, 7u);
    EXPECT_NEAR(scene.buildings[0].eaves, 21.3f, 1e-4f);
    EXPECT_GT(scene.buildings[0].ridge, 27.0f);
    const Material *masonry = findMaterial(scene, "(building 7 masonry)");
    ASSERT_NE(masonry, nullptr);
    EXPECT_NE(masonry->diffuseMap, kNoTexture);
    EXPECT_NE(masonry->normalMap, kNoTexture);
    ASSERT_TRUE(scene.textures);
    EXPECT_EQ(scene.textures->channels(masonry->diffuseMap), 4);
    // The walls that show it have their texture coordinates inside the atlas.
    MaterialId id = MaterialId(masonry - scene.materials.data());
    size_t shown = 0;
    for (const BakedMesh &baked : scene.meshes) {
        const Mesh &mesh = baked.mesh;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            if (mesh.triangleMaterials[t] != id) continue;
            ++shown;
            for (int k = 0; k < 3; ++k) {
                Vec2f uv = mesh.uvs[mesh.indices[3 * t + size_t(k)]];
                EXPECT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1) << uv.x << " " << uv.y;
            }
        }
    }
    EXPECT_GT(shown, 100u);
}

TEST(ModularBuildings, AStyleNamingAMaterialTheSceneLacksIsRefusedAtTheStyle) {
    std::string xml = R"(<scene version="1"><modular_building structure="palace/palace.structure"
        style="palace/brick.style"/></scene>)";
    std::string message =
        test::inputErrorOf([&] { buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes"))); });
    EXPECT_NE(message.find("brick.style:4:1: style 'brick': the scene has no material called"), std::string::npos)
        << message;
}

TEST(ModularBuildings, AMissingStructureFileIsSaidAtItsAttribute) {
    std::string message =
        test::inputErrorOf([&] { build(R"(<modular_building structure="palace/none.structure" style="x"/>)"); });
    EXPECT_NE(message.find("none.structure"), std::string::npos) << message;
}

}  // namespace
}  // namespace veduta
