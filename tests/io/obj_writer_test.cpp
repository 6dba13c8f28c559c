// The OBJ writer's text: an object per baked mesh and instance copy, materials with maps copied
// beside the file, glass as MTL knows it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/scene_export.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path &file) {
    std::stringstream text;
    text << std::ifstream(file).rdbuf();
    return text.str();
}

size_t linesStartingWith(const std::string &text, const std::string &start) {
    size_t count = 0;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) count += line.starts_with(start) ? 1 : 0;
    return count;
}

TEST(ObjWriter, AnObjectPerMeshAndCopyWithMaterialsAndMaps) {
    std::string map = test::sourceFile("materials/textures/brick_diffuse.png");
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <material name="brick" diffuse="0.6 0.25 0.2" diffuse_map=")" +
                                           map + R"("/>
  <material name="pane" glass="true" ior="1.52" tint="0.9 0.95 0.9"/>
  <box size="4 4 3" material="brick" id="17" building="3"/>
  <plane size="2 2" material="pane" translate="0 -2.01 1.5" id="18"/>
  <prototype name="spire"><cone radius="0.5" height="2" segments="6"/></prototype>
  <instance prototype="spire" translate="10 0 0" id="20"/>
  <instance prototype="spire" translate="0 10 0" id="21"/>
</scene>)");
    ExportOptions options;
    for (const Material &m : scene.materials)
        if (m.name == "brick") options.textureFiles[m.diffuseMap] = map;
    test::ScratchFolder folder("obj_writer");
    ExportStats stats = exportScene(scene, folder.path() / "city.obj", ExportFormat::Obj, options);
    EXPECT_EQ(stats.files, 3u);  // .obj, .mtl, the map
    EXPECT_EQ(stats.meshes, 4u);
    std::string obj = readText(folder.path() / "city.obj");
    EXPECT_EQ(linesStartingWith(obj, "o "), 4u);
    EXPECT_NE(obj.find("\no building_3/object_17\n"), std::string::npos);
    EXPECT_NE(obj.find("\no object_21\n"), std::string::npos);
    EXPECT_EQ(linesStartingWith(obj, "f "), scene.effectiveTriangleCount());
    EXPECT_NE(obj.find("mtllib city.mtl\n"), std::string::npos);
    std::string mtl = readText(folder.path() / "city.mtl");
    EXPECT_NE(mtl.find("newmtl brick\n"), std::string::npos);
    EXPECT_NE(mtl.find("map_Kd brick_diffuse.png\n"), std::string::npos);
    EXPECT_NE(mtl.find("Ni 1.52\n"), std::string::npos);
    EXPECT_NE(mtl.find("illum 7\n"), std::string::npos);
    EXPECT_EQ(fs::file_size(folder.path() / "brick_diffuse.png"), fs::file_size(map));
}

}  // namespace
}  // namespace veduta
