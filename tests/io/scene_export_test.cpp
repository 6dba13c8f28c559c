#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "core/axes.h"
#include "io/export_scene.h"
#include "io/scene_export.h"
#include "test_scenes.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

class SceneExport : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
            ("veduta-export-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        scene_ = test::sceneFromXml(test::exportSceneXml());
    }
    void TearDown() override {
        if (!::testing::Test::HasFailure()) fs::remove_all(folder_);
    }

    fs::path folder_;
    RenderScene scene_;
};

const aiScene *readBack(Assimp::Importer &importer, const fs::path &file) {
    const aiScene *scene = importer.ReadFile(file.string(), 0);
    EXPECT_NE(scene, nullptr) << importer.GetErrorString();
    return scene;
}

struct WorldGeometry {
    size_t triangles = 0;
    std::vector<Vec3f> positions;
};

// Every triangle of the file in world space, node transforms applied.
void collect(const aiScene &scene, const aiNode &node, const aiMatrix4x4 &parent, WorldGeometry &out) {
    aiMatrix4x4 toWorld = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh &mesh = *scene.mMeshes[node.mMeshes[i]];
        out.triangles += mesh.mNumFaces;
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            aiVector3D p = toWorld * mesh.mVertices[v];
            out.positions.push_back({p.x, p.y, p.z});
        }
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) collect(scene, *node.mChildren[i], toWorld, out);
}

WorldGeometry worldGeometry(const aiScene &scene) {
    WorldGeometry out;
    collect(scene, *scene.mRootNode, aiMatrix4x4(), out);
    return out;
}

// Whether `p` is within a millimetre of one of `positions`.
bool contains(const std::vector<Vec3f> &positions, const Vec3f &p) {
    return std::any_of(positions.begin(), positions.end(), [&](const Vec3f &q) { return length(q - p) < 1e-3f; });
}

// Every vertex the scene draws, in world space.
std::vector<Vec3f> sceneVertices(const RenderScene &scene) {
    std::vector<Vec3f> out;
    for (const BakedMesh &baked : scene.meshes)
        out.insert(out.end(), baked.mesh.positions.begin(), baked.mesh.positions.end());
    for (const Instance &instance : scene.instances) {
        for (const Vec3f &p : scene.prototypes[instance.prototype].positions)
            out.push_back(instance.objectToWorld.applyPoint(p));
    }
    return out;
}

const aiMaterial *materialNamed(const aiScene &scene, const std::string &name) {
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
        if (scene.mMaterials[i]->GetName().C_Str() == name) return scene.mMaterials[i];
    }
    return nullptr;
}

// The materials the geometry uses (Assimp's glTF reader skips the others).
void expectMaterialsSurvive(const aiScene &file, const RenderScene &scene) {
    for (const Material &m : scene.materials) {
        if (m.name == "default") continue;
        const aiMaterial *read = materialNamed(file, m.name);
        ASSERT_NE(read, nullptr) << m.name;
        aiColor3D diffuse;
        ASSERT_EQ(read->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse), AI_SUCCESS) << m.name;
        Vec3f expected = m.glass ? m.glassTint : m.diffuse;
        EXPECT_NEAR(diffuse.r, expected.x, 1e-5f) << m.name;
        EXPECT_NEAR(diffuse.g, expected.y, 1e-5f) << m.name;
        EXPECT_NEAR(diffuse.b, expected.z, 1e-5f) << m.name;
    }
}

TEST_F(SceneExport, TheTestSceneHasBakedAndInstancedGeometry) {
    ASSERT_EQ(scene_.meshes.size(), 2u);
    ASSERT_EQ(scene_.prototypes.size(), 1u);
    ASSERT_EQ(scene_.instances.size(), 3u);
}

TEST_F(SceneExport, ObjWritesInstancesAsCopiesZUp) {
    fs::path file = folder_ / "city.obj";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Obj);
    EXPECT_EQ(stats.files, 2u);
    EXPECT_EQ(stats.instances, 3u);
    EXPECT_EQ(stats.meshes, 5u);
    EXPECT_EQ(stats.triangles, scene_.effectiveTriangleCount());
    EXPECT_TRUE(fs::is_regular_file(folder_ / "city.mtl"));

    Assimp::Importer importer;
    const aiScene *read = readBack(importer, file);
    ASSERT_NE(read, nullptr);
    WorldGeometry geometry = worldGeometry(*read);
    EXPECT_EQ(geometry.triangles, scene_.effectiveTriangleCount());
    for (const Vec3f &p : sceneVertices(scene_))
        EXPECT_TRUE(contains(geometry.positions, p)) << p.x << " " << p.y << " " << p.z;
    expectMaterialsSurvive(*read, scene_);
}

TEST_F(SceneExport, MtlHasPhongAndGlass) {
    exportScene(scene_, folder_ / "city.obj", ExportFormat::Obj);
    Assimp::Importer importer;
    const aiScene *read = readBack(importer, folder_ / "city.obj");
    ASSERT_NE(read, nullptr);
    const aiMaterial *brick = materialNamed(*read, "brick");
    ASSERT_NE(brick, nullptr);
    float shininess = 0;
    ASSERT_EQ(brick->Get(AI_MATKEY_SHININESS, shininess), AI_SUCCESS);
    EXPECT_FLOAT_EQ(shininess, 16);
    aiColor3D specular;
    ASSERT_EQ(brick->Get(AI_MATKEY_COLOR_SPECULAR, specular), AI_SUCCESS);
    EXPECT_NEAR(specular.r, scene_.materials[1].specular.x, 1e-5f);
    const aiMaterial *pane = materialNamed(*read, "pane");
    ASSERT_NE(pane, nullptr);
    float ior = 0, opacity = 1;
    ASSERT_EQ(pane->Get(AI_MATKEY_REFRACTI, ior), AI_SUCCESS);
    EXPECT_FLOAT_EQ(ior, 1.52f);
    ASSERT_EQ(pane->Get(AI_MATKEY_OPACITY, opacity), AI_SUCCESS);
    EXPECT_LT(opacity, 0.1f);
}

// glTF keeps the prototype once and places it by three nodes; the file is Y up.
void expectGltfInstancing(const fs::path &file, const RenderScene &scene) {
    Assimp::Importer importer;
    const aiScene *read = readBack(importer, file);
    ASSERT_NE(read, nullptr);
    // One mesh per baked mesh and per prototype: each uses a single material here.
    EXPECT_EQ(read->mNumMeshes, scene.meshes.size() + scene.prototypes.size());
    std::vector<unsigned> prototypeUses(read->mNumMeshes, 0);
    std::vector<const aiNode *> nodes{read->mRootNode};
    while (!nodes.empty()) {
        const aiNode *node = nodes.back();
        nodes.pop_back();
        for (unsigned i = 0; i < node->mNumMeshes; ++i) ++prototypeUses[node->mMeshes[i]];
        nodes.insert(nodes.end(), node->mChildren, node->mChildren + node->mNumChildren);
    }
    EXPECT_EQ(std::count(prototypeUses.begin(), prototypeUses.end(), 3u), 1);
    EXPECT_EQ(std::count(prototypeUses.begin(), prototypeUses.end(), 1u), 2);
    ASSERT_NE(read->mRootNode->FindNode("building_3/object_17"), nullptr);
    ASSERT_NE(read->mRootNode->FindNode("object_21"), nullptr);

    WorldGeometry geometry = worldGeometry(*read);
    EXPECT_EQ(geometry.triangles, scene.effectiveTriangleCount());
    for (Vec3f &p : geometry.positions) p = yUpToZUp(p);
    for (const Vec3f &p : sceneVertices(scene))
        EXPECT_TRUE(contains(geometry.positions, p)) << p.x << " " << p.y << " " << p.z;
    expectMaterialsSurvive(*read, scene);
}

TEST_F(SceneExport, GltfKeepsInstancingYUp) {
    fs::path file = folder_ / "city.gltf";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Gltf);
    EXPECT_EQ(stats.files, 2u);
    EXPECT_EQ(stats.meshes, 3u);
    EXPECT_EQ(stats.instances, 3u);
    EXPECT_TRUE(fs::is_regular_file(folder_ / "city.bin"));
    expectGltfInstancing(file, scene_);
}

TEST_F(SceneExport, GlbIsOneFileWithInstancing) {
    fs::path file = folder_ / "city.glb";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Glb);
    EXPECT_EQ(stats.files, 1u);
    EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
    expectGltfInstancing(file, scene_);
}

TEST_F(SceneExport, GltfGlassIsTransmissive) {
    exportScene(scene_, folder_ / "city.glb", ExportFormat::Glb);
    Assimp::Importer importer;
    const aiScene *read = readBack(importer, folder_ / "city.glb");
    ASSERT_NE(read, nullptr);
    float transmission = 0, roughness = 1;
    ASSERT_EQ(materialNamed(*read, "pane")->Get(AI_MATKEY_TRANSMISSION_FACTOR, transmission), AI_SUCCESS);
    EXPECT_EQ(transmission, 1.0f);
    // Phong n = 16 with a specular colour: (2 / 18)^(1/4).
    ASSERT_EQ(materialNamed(*read, "brick")->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), AI_SUCCESS);
    EXPECT_NEAR(roughness, 0.5774f, 1e-4f);
    // No specular colour: matte.
    ASSERT_EQ(materialNamed(*read, "slate")->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), AI_SUCCESS);
    EXPECT_EQ(roughness, 1.0f);
}

TEST_F(SceneExport, FormatFromExtension) {
    EXPECT_EQ(exportFormatForPath("a/b.obj"), ExportFormat::Obj);
    EXPECT_EQ(exportFormatForPath("b.GLTF"), ExportFormat::Gltf);
    EXPECT_EQ(exportFormatForPath("b.glb"), ExportFormat::Glb);
    EXPECT_EQ(exportFormatForPath("b.Ply"), ExportFormat::Ply);
    EXPECT_EQ(exportFormatForPath("b.fbx"), std::nullopt);
    EXPECT_EQ(exportFormatForPath("obj"), std::nullopt);
}

// A faceted pyramid shares its vertices between faces; the OBJ must still shade it flat.
TEST_F(SceneExport, FacetedMeshesKeepFaceNormals) {
    RenderScene pyramid = test::sceneFromXml(R"(<scene><cone segments="4" smooth="false"/></scene>)");
    ASSERT_TRUE(pyramid.meshes[0].mesh.normals.empty());
    exportScene(pyramid, folder_ / "pyramid.obj", ExportFormat::Obj);
    Assimp::Importer importer;
    const aiScene *read = readBack(importer, folder_ / "pyramid.obj");
    ASSERT_NE(read, nullptr);
    size_t triangles = 0;
    for (unsigned m = 0; m < read->mNumMeshes; ++m) {
        const aiMesh &mesh = *read->mMeshes[m];
        ASSERT_TRUE(mesh.HasNormals());
        for (unsigned f = 0; f < mesh.mNumFaces; ++f, ++triangles) {
            const unsigned *idx = mesh.mFaces[f].mIndices;
            aiVector3D face =
                (mesh.mVertices[idx[1]] - mesh.mVertices[idx[0]]) ^ (mesh.mVertices[idx[2]] - mesh.mVertices[idx[0]]);
            face.Normalize();
            for (int k = 0; k < 3; ++k) EXPECT_NEAR((mesh.mNormals[idx[k]] - face).Length(), 0, 1e-5f);
        }
    }
    EXPECT_EQ(triangles, pyramid.effectiveTriangleCount());
}

// A folder stands where the .obj goes: nothing is written, and the folder stays.
TEST_F(SceneExport, AFailedExportLeavesNothing) {
    fs::create_directory(folder_ / "city.obj");
    EXPECT_THROW(exportScene(scene_, folder_ / "city.obj", ExportFormat::Obj), std::exception);
    EXPECT_TRUE(fs::is_empty(folder_ / "city.obj"));
    EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace veduta
