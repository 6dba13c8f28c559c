// The glTF writer's files read back through tinygltf's loader, an implementation of the
// specification that is not veduta's: counts, instancing, camera, sun, glass, maps and the
// georeference.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <tiny_gltf.h>

#include "core/axes.h"
#include "io/export_scene.h"
#include "io/image_library.h"
#include "io/scene_export.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

namespace fs = std::filesystem;

std::string sceneXml() {
    return test::exportSceneXml(
        R"(  <camera position="0 -10 2" look_at="0 0 2" up="0 0 1" fov="50" resolution="800 400"/>
  <sun azimuth="180" elevation="30" irradiance="3.2 3.05 2.8"/>
)",
        "diffuse_map=\"" + test::sourceFile("materials/textures/brick_diffuse.png") + "\" normal_map=\"" +
            test::sourceFile("materials/textures/brick_normal.png") + "\"");
}

class GltfWriter : public ::testing::Test {
  protected:
    void SetUp() override {
        scene_ = test::sceneFromXml(sceneXml());
        const Material &brick = sceneMaterial("brick");
        options_.textureFiles = {{brick.diffuseMap, test::sourceFile("materials/textures/brick_diffuse.png")},
                                 {brick.normalMap, test::sourceFile("materials/textures/brick_normal.png")}};
        options_.georeference = Georeference{25832, 531200, 5326800};
    }

    Material &sceneMaterial(const std::string &name) {
        for (Material &m : scene_.materials)
            if (m.name == name) return m;
        throw std::runtime_error("no material " + name);
    }

    tinygltf::Model load(const fs::path &file) {
        tinygltf::TinyGLTF loader;
        tinygltf::Model model;
        std::string error, warning;
        bool ok = file.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                                             : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
        EXPECT_TRUE(ok) << error;
        EXPECT_EQ(warning, "");
        return model;
    }

    const tinygltf::Material &material(const tinygltf::Model &model, const std::string &name) {
        for (const tinygltf::Material &m : model.materials)
            if (m.name == name) return m;
        throw std::runtime_error("no material " + name);
    }

    const tinygltf::Node &node(const tinygltf::Model &model, const std::string &name) {
        for (const tinygltf::Node &n : model.nodes)
            if (n.name == name) return n;
        throw std::runtime_error("no node " + name);
    }

    test::ScratchFolder folder_{"gltf_writer"};
    RenderScene scene_;
    ExportOptions options_;
};

// Nodes: two baked meshes, three instances of one prototype, the camera and the sun.
TEST_F(GltfWriter, CountsAndInstancing) {
    fs::path file = folder_.path() / "city.gltf";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Gltf, options_);
    // .gltf, .bin, two images, .prj, .geo.json
    EXPECT_EQ(stats.files, 6u);
    EXPECT_EQ(stats.textures, 2u);
    tinygltf::Model model = load(file);
    ASSERT_EQ(scene_.meshes.size(), 2u);
    EXPECT_EQ(model.nodes.size(), 2u + 3u + 2u);
    EXPECT_EQ(model.meshes.size(), 3u);
    EXPECT_EQ(model.materials.size(), scene_.materials.size());
    EXPECT_EQ(model.scenes.at(0).nodes.size(), model.nodes.size());
    int spire = node(model, "object_20").mesh;
    EXPECT_EQ(node(model, "object_21").mesh, spire);
    EXPECT_EQ(node(model, "object_22").mesh, spire);
    EXPECT_EQ(model.meshes.at(size_t(spire)).name, "prototype_0/slate");
    EXPECT_GE(node(model, "building_3/object_17").mesh, 0);
    // Instance 20 sits at x 10 (Z up), which stays x 10 in Y up; 22 at z 10, which is y 10.
    EXPECT_FLOAT_EQ(float(node(model, "object_20").matrix.at(12)), 10);
    EXPECT_FLOAT_EQ(float(node(model, "object_22").matrix.at(13)), 10);
    for (const tinygltf::Accessor &a : model.accessors) EXPECT_GT(a.count, 0u);
}

TEST_F(GltfWriter, PositionsHaveBoundsAndStayInTheirPlace) {
    fs::path file = folder_.path() / "city.glb";
    exportScene(scene_, file, ExportFormat::Glb, options_);
    tinygltf::Model model = load(file);
    const tinygltf::Mesh &box = model.meshes.at(size_t(node(model, "building_3/object_17").mesh));
    const tinygltf::Accessor &positions = model.accessors.at(size_t(box.primitives.at(0).attributes.at("POSITION")));
    ASSERT_EQ(positions.minValues.size(), 3u);
    ASSERT_EQ(positions.maxValues.size(), 3u);
    // The box spans x ±2, y ±2, z 0 … 3 in veduta's frame: in Y up, y 0 … 3 and z ±2.
    EXPECT_FLOAT_EQ(float(positions.minValues[0]), -2);
    EXPECT_FLOAT_EQ(float(positions.maxValues[1]), 3);
    EXPECT_FLOAT_EQ(float(positions.minValues[2]), -2);
    EXPECT_EQ(positions.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::Accessor &indices = model.accessors.at(size_t(box.primitives.at(0).indices));
    EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
}

TEST_F(GltfWriter, CameraLooksAsTheRenderDoes) {
    fs::path file = folder_.path() / "city.gltf";
    exportScene(scene_, file, ExportFormat::Gltf, options_);
    tinygltf::Model model = load(file);
    ASSERT_EQ(model.cameras.size(), 1u);
    const tinygltf::Camera &camera = model.cameras[0];
    EXPECT_EQ(camera.type, "perspective");
    EXPECT_NEAR(camera.perspective.yfov, 50 * M_PI / 180, 1e-6);
    EXPECT_NEAR(camera.perspective.aspectRatio, 2.0, 1e-6);
    const std::vector<double> &m = node(model, "camera").matrix;
    ASSERT_EQ(m.size(), 16u);
    // The camera looks along +y in veduta (−z in Y up): its node's −Z column must say so.
    Vec3f forward = yUpToZUp(Vec3f{float(-m[8]), float(-m[9]), float(-m[10])});
    EXPECT_NEAR(forward.y, 1, 1e-6);
    Vec3f position = yUpToZUp(Vec3f{float(m[12]), float(m[13]), float(m[14])});
    EXPECT_NEAR(position.y, -10, 1e-5);
    EXPECT_NEAR(position.z, 2, 1e-5);
}

TEST_F(GltfWriter, SunIsADirectionalLightInLux) {
    fs::path file = folder_.path() / "city.gltf";
    exportScene(scene_, file, ExportFormat::Gltf, options_);
    tinygltf::Model model = load(file);
    ASSERT_EQ(model.lights.size(), 1u);
    EXPECT_EQ(model.lights[0].type, "directional");
    EXPECT_NEAR(model.lights[0].intensity, 3.2 * 683, 1e-3);
    EXPECT_NEAR(model.lights[0].color.at(1), 3.05 / 3.2, 1e-6);
    // The light shines down its node's −Z, away from the sun: from the south, up 30°.
    const std::vector<double> &m = node(model, "sun").matrix;
    Vec3f towardsSun = yUpToZUp(Vec3f{float(m[8]), float(m[9]), float(m[10])});
    EXPECT_NEAR(towardsSun.x, scene_.sun.direction.x, 1e-5);
    EXPECT_NEAR(towardsSun.y, scene_.sun.direction.y, 1e-5);
    EXPECT_NEAR(towardsSun.z, scene_.sun.direction.z, 1e-5);
    EXPECT_LT(towardsSun.y, 0);
}

TEST_F(GltfWriter, GlassIsClearAndTransmissive) {
    fs::path file = folder_.path() / "city.glb";
    exportScene(scene_, file, ExportFormat::Glb, options_);
    tinygltf::Model model = load(file);
    const tinygltf::Material &pane = material(model, "pane");
    EXPECT_EQ(pane.pbrMetallicRoughness.roughnessFactor, 0);
    ASSERT_TRUE(pane.extensions.count("KHR_materials_transmission"));
    EXPECT_EQ(pane.extensions.at("KHR_materials_transmission").Get("transmissionFactor").GetNumberAsDouble(), 1);
    EXPECT_NEAR(pane.extensions.at("KHR_materials_ior").Get("ior").GetNumberAsDouble(), 1.52, 1e-6);
    // Phong n = 16 with a specular colour: (2 / 18)^(1/4); no specular colour: matte.
    EXPECT_NEAR(material(model, "brick").pbrMetallicRoughness.roughnessFactor, 0.5774, 1e-4);
    EXPECT_EQ(material(model, "slate").pbrMetallicRoughness.roughnessFactor, 1);
}

TEST_F(GltfWriter, MapsBecomeTexturesWithTangents) {
    for (const char *name : {"city.gltf", "city.glb"}) {
        fs::path file = folder_.path() / name;
        exportScene(scene_, file, *exportFormatForPath(file), options_);
        tinygltf::Model model = load(file);
        ASSERT_EQ(model.images.size(), 2u) << name;
        const tinygltf::Material &brick = material(model, "brick");
        int diffuse = brick.pbrMetallicRoughness.baseColorTexture.index;
        ASSERT_GE(diffuse, 0);
        ASSERT_GE(brick.normalTexture.index, 0);
        // The loader decoded the image: it is the 8-bit file, in the .glb or beside the .gltf.
        EXPECT_GT(model.images.at(size_t(model.textures.at(size_t(diffuse)).source)).width, 0) << name;
        const tinygltf::Mesh &box = model.meshes.at(size_t(node(model, "building_3/object_17").mesh));
        EXPECT_TRUE(box.primitives.at(0).attributes.count("TANGENT")) << name;
        EXPECT_TRUE(box.primitives.at(0).attributes.count("TEXCOORD_0")) << name;
    }
    EXPECT_TRUE(fs::is_regular_file(folder_.path() / "brick_diffuse.png"));
}

TEST_F(GltfWriter, GeoreferenceInExtrasAndSidecars) {
    fs::path file = folder_.path() / "city.gltf";
    exportScene(scene_, file, ExportFormat::Gltf, options_);
    tinygltf::Model model = load(file);
    const tinygltf::Value &veduta = model.asset.extras.Get("veduta");
    EXPECT_EQ(veduta.Get("crs").Get<std::string>(), "EPSG:25832");
    EXPECT_EQ(veduta.Get("origin").Get(0).GetNumberAsDouble(), 531200);
    EXPECT_EQ(veduta.Get("origin").Get(1).GetNumberAsDouble(), 5326800);
    EXPECT_EQ(veduta.Get("up").Get<std::string>(), "Y");
    std::stringstream prj;
    prj << std::ifstream(folder_.path() / "city.prj").rdbuf();
    EXPECT_NE(prj.str().find("PROJCS[\"ETRS_1989_UTM_Zone_32N\""), std::string::npos) << prj.str();
    std::stringstream json;
    json << std::ifstream(folder_.path() / "city.geo.json").rdbuf();
    EXPECT_NE(json.str().find("\"origin\": [531200, 5326800, 0]"), std::string::npos) << json.str();
}

TEST_F(GltfWriter, NoGeoreferenceIsSaidAndWritesNoSidecar) {
    options_.georeference.reset();
    fs::path file = folder_.path() / "local.glb";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Glb, options_);
    EXPECT_EQ(stats.files, 1u);
    tinygltf::Model model = load(file);
    EXPECT_FALSE(model.asset.extras.Get("veduta").Get("georeferenced").Get<bool>());
    EXPECT_FALSE(fs::exists(folder_.path() / "local.prj"));
}

// glTF takes PNG and JPEG only: an EXR diffuse map arrives as a PNG with the sRGB transfer.
TEST_F(GltfWriter, OtherMapFormatsAreConvertedToPng) {
    Image grey;
    grey.width = grey.height = 2;
    grey.channels = 3;
    grey.pixels.assign(12, 0.5f);
    fs::path exr = folder_.path() / "grey.exr";
    imageLibrary().write(exr, grey);
    Material &slate = sceneMaterial("slate");
    slate.diffuseMap = 99;  // no registry lookup: the export goes by the file
    options_.textureFiles[slate.diffuseMap] = exr;
    fs::path file = folder_.path() / "out" / "city.glb";
    fs::create_directories(file.parent_path());
    ExportStats stats = exportScene(scene_, file, ExportFormat::Glb, options_);
    EXPECT_EQ(stats.textures, 3u);
    tinygltf::Model model = load(file);
    int texture = material(model, "slate").pbrMetallicRoughness.baseColorTexture.index;
    ASSERT_GE(texture, 0);
    const tinygltf::Image &png = model.images.at(size_t(model.textures.at(size_t(texture)).source));
    EXPECT_EQ(png.mimeType, "image/png");
    ASSERT_EQ(png.width, 2);
    // Linear 0.5 is sRGB 0.7354: 188 of 255.
    EXPECT_NEAR(png.image.at(0), 188, 1);
}

// A map with no file behind it: its material keeps the map's mean colour, and the note says so.
class ProceduralGrey final : public Textures {
  public:
    TextureId add(const fs::path &, const std::string &) override { return 0; }
    TextureId add(Image) override { return 0; }
    TextureId add(std::shared_ptr<const ProceduralTexture>) override { return 0; }
    int channels(TextureId) const override { return 1; }
    std::string fingerprint(TextureId) const override { return "procedural:grey"; }
    void lookup(TextureId, Vec2f, float, float *out, int count) const override {
        for (int i = 0; i < count; ++i) out[i] = 0.5f;
    }
};

TEST_F(GltfWriter, ProceduralMapsKeepTheirMeanColourAndAreCounted) {
    scene_.textures = std::make_shared<ProceduralGrey>();
    sceneMaterial("slate").diffuseMap = 0;
    options_.textureFiles.clear();
    fs::path file = folder_.path() / "city.glb";
    ExportStats stats = exportScene(scene_, file, ExportFormat::Glb, options_);
    EXPECT_EQ(stats.notes.at("materials keep only their mean colour: procedural texture"), 2u);  // slate, brick
    tinygltf::Model model = load(file);
    EXPECT_NEAR(material(model, "slate").pbrMetallicRoughness.baseColorFactor.at(0), 0.2 * 0.5, 1e-6);
    EXPECT_LT(material(model, "slate").pbrMetallicRoughness.baseColorTexture.index, 0);
}

}  // namespace
}  // namespace veduta
