// The PLY writer's header and the size of its binary body.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/scene_export.h"
#include "test_scenes.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

TEST(PlyWriter, HeaderCountsAndBodySize) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <material name="brick" diffuse="0.6 0.25 0.2"/>
  <box size="4 4 3" material="brick" id="17"/>
  <prototype name="spire"><cone radius="0.5" height="2" segments="6"/></prototype>
  <instance prototype="spire" translate="10 0 0" id="20"/>
  <instance prototype="spire" translate="0 10 0" id="21"/>
</scene>)");
    test::ScratchFolder folder("ply_writer");
    fs::path file = folder.path() / "city.ply";
    ExportStats stats = exportScene(scene, file, ExportFormat::Ply);
    EXPECT_EQ(stats.files, 1u);
    std::ifstream in(file, std::ios::binary);
    std::string line, header;
    size_t vertices = 0, faces = 0;
    bool uvs = false;
    while (std::getline(in, line) && line != "end_header") {
        header += line + "\n";
        if (line.starts_with("element vertex ")) vertices = std::stoul(line.substr(15));
        if (line.starts_with("element face ")) faces = std::stoul(line.substr(13));
        uvs = uvs || line == "property float s";
    }
    ASSERT_EQ(line, "end_header");
    EXPECT_EQ(header.substr(0, 36), "ply\nformat binary_little_endian 1.0\n");
    EXPECT_NE(header.find("comment material 1 brick\n"), std::string::npos);
    EXPECT_NE(header.find("property uchar red\n"), std::string::npos);
    EXPECT_EQ(faces, scene.effectiveTriangleCount());
    size_t vertexBytes = 4 * (6 + (uvs ? 2 : 0)) + 3;
    size_t faceBytes = 1 + 3 * 4 + 4;
    EXPECT_EQ(fs::file_size(file), size_t(in.tellg()) + vertices * vertexBytes + faces * faceBytes);
}

}  // namespace
}  // namespace veduta
