// importMesh on files others wrote: PLY goes through veduta's own reader (Assimp's loops for
// ever on some broken headers and cut bodies), the rest through Assimp, and every failure is an
// InputError naming the file, at once.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>

#include "input_error.h"
#include "io/mesh_import.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

const std::string kQuadHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kQuadBody = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";

class MeshImport : public testing::Test {
  protected:
    test::ScratchFolder folder_{"mesh_import"};
};

TEST_F(MeshImport, PlyQuadBecomesTwoTriangles) {
    Mesh mesh = importMesh(folder_.write("quad.PLY", kQuadHeader + kQuadBody));
    EXPECT_EQ(mesh.vertexCount(), 4u);
    EXPECT_EQ(mesh.triangleCount(), 2u);
    EXPECT_EQ(mesh.triangleMaterials.size(), 2u);
}

// The input on which Assimp's PLY parser never returned (found by fuzz/mesh_ply).
TEST_F(MeshImport, PlyWithAMisspeltHeaderLineIsRefusedAtOnce) {
    std::ifstream in(test::sourceFile("fuzz/regressions/mesh_ply/misspelt_element_loops_assimp.ply"), std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    ASSERT_FALSE(text.empty());
    auto file = folder_.write("misspelt.ply", text);
    auto start = std::chrono::steady_clock::now();
    std::string error = test::inputErrorOf([&] { importMesh(file); });
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_EQ(error.rfind(file.string() + ":8: ", 0), 0u) << error;
}

// A .gltf that no glTF reader takes: Assimp went on to offer it to all its readers, and the MD5
// reader's token search read past the end of the file (found by fuzz/mesh_gltf under ASan).
// Only the readers of the extension see the file now.
TEST_F(MeshImport, AFileNoReaderOfItsExtensionTakesIsRefused) {
    std::ifstream in(test::sourceFile("fuzz/regressions/mesh_gltf/md5_token_search_reads_past_the_end.gltf"),
                     std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    ASSERT_FALSE(text.empty());
    auto file = folder_.write("md5.gltf", text);
    std::string error = test::inputErrorOf([&] { importMesh(file); });
    EXPECT_EQ(error.rfind(file.string() + ": cannot read mesh: ", 0), 0u) << error;
    // An OBJ in a file named .stl is an STL file to read, not an OBJ to guess.
    auto misnamed = folder_.write("triangle.stl", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(test::inputErrorOf([&] { importMesh(misnamed); }), "no error");
    auto bare = folder_.write("triangle", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(test::inputErrorOf([&] { importMesh(bare); }),
              bare.string() + ": a mesh file needs an extension that names its format (.obj, .gltf, .glb, …)");
}

// An OBJ whose only line fills the file: Assimp cut it into a buffer as large as the file and
// gave strtol the last token with no terminator (found by fuzz/mesh_obj under ASan's strict
// string checks, which the sanitize preset runs this test with). The file is read with a
// newline and a NUL after it now, and its "p" (point) statement of no index is refused by
// name. A triangle whose file ends in a digit without a newline is read whole.
TEST_F(MeshImport, AnObjWhoseLastLineFillsTheFileIsReadWithinIt) {
    std::ifstream in(test::sourceFile("fuzz/regressions/mesh_obj/last_line_filling_the_file_unterminated.obj"),
                     std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    ASSERT_EQ(text.size(), 16u);
    auto file = folder_.write("filled.obj", text);
    EXPECT_EQ(test::inputErrorOf([&] { importMesh(file); }),
              file.string() + ": cannot read mesh: OBJ: Invalid face index.");
    auto unterminated = folder_.write("unterminated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3");
    EXPECT_EQ(importMesh(unterminated).triangleCount(), 1u);
}

TEST_F(MeshImport, CutPlyIsRefused) {
    std::string whole = kQuadHeader + kQuadBody;
    auto file = folder_.write("cut.ply", whole.substr(0, whole.size() - 8));
    std::string error = test::inputErrorOf([&] { importMesh(file); });
    EXPECT_EQ(error.rfind(file.string() + ":", 0), 0u) << error;
}

// Found by fuzz/mesh_ply: items without properties read no bytes, so their count was looped
// through for ever; a count the file cannot hold is refused as well.
TEST_F(MeshImport, PlyCountsTheFileCannotHoldAreRefusedAtOnce) {
    auto empty = folder_.write("empty.ply", "ply\nformat ascii 1.0\nelement face 888888888888\nend_header\n");
    EXPECT_EQ(test::inputErrorOf([&] { importMesh(empty); }),
              empty.string() + ":3: the element 'face' has 888888888888 items but no properties");
    std::string header = kQuadHeader;
    header.replace(header.find("vertex 4"), 8, "vertex 4000");
    auto many = folder_.write("many.ply", header + kQuadBody);
    EXPECT_EQ(test::inputErrorOf([&] {
                  importMesh(many);
              }).rfind(many.string() + ":3: the element 'vertex' promises 4000 items, more than the file's ", 0),
              0u);
}

// Found by fuzz/mesh_ply: a face index beyond 32 bits was converted to one (undefined).
TEST_F(MeshImport, PlyFaceIndexBeyondAnyVertexIsRefused) {
    std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 6.7e62\n";
    auto file = folder_.write("far_index.ply", kQuadHeader + body);
    std::string error = test::inputErrorOf([&] { importMesh(file); });
    EXPECT_EQ(error.rfind(file.string() + ":14: face 0 refers to vertex 6.7e+62", 0), 0u) << error;
}

TEST_F(MeshImport, PlyVertexBeyondSinglePrecisionIsRefused) {
    std::string body = "0 0 0\n1e39 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    std::string header = kQuadHeader;
    for (size_t at = header.find("float"); at != std::string::npos; at = header.find("float", at))
        header.replace(at, 5, "double");
    auto file = folder_.write("far.ply", header + body);
    EXPECT_EQ(test::inputErrorOf([&] { importMesh(file); }),
              file.string() + ": vertex 1 is not a finite point in single precision (1e+39 0 0)");
}

}  // namespace
}  // namespace veduta
