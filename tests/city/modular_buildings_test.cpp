// <modular_building> in scene files: Finkenzeller's palace from its structure and style files,
// its masonry shaded procedurally or baked into an atlas the walls show.
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "assembly/build_scene.h"
#include "city/modular_buildings.h"
#include "core/rgba_image.h"
#include "film/passes.h"
#include "input_error.h"
#include "render/bvh.h"
#include "render/renderer.h"
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
    RenderScene scene = build(R"(<render masonry="baked"/>
            <modular_building structure="palace/palace.structure" style="palace/brick.style" building="7"/>)",
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

// <render masonry="procedural">: the palace's brick shaded where it is looked up. Its walls read
// the shader's maps, and the palace seen whole shows the colour the baked atlas gives it: the
// same stones and mortar, averaged by the pixels instead of the atlas's texels.
TEST(ModularBuildings, ThePalaceInBrickShadedProcedurallyShowsTheBakedColour) {
    auto palace = [](const char *masonry) {
        return build(fmt::format(R"(<render spp="16" max_depth="3" masonry="{}"/>
            <modular_building structure="palace/palace.structure" style="palace/brick.style" building="7"/>)",
                                 masonry));
    };
    RenderScene baked = palace("baked"), shaded = palace("procedural");
    const Material *masonry = findMaterial(shaded, "(building 7 masonry)");
    ASSERT_NE(masonry, nullptr);
    EXPECT_EQ(shaded.textures->fingerprint(masonry->diffuseMap).rfind("procedural:masonry ", 0), 0u)
        << shaded.textures->fingerprint(masonry->diffuseMap);
    EXPECT_EQ(shaded.textures->channels(masonry->diffuseMap), 3);
    auto image = [](const RenderScene &scene) {
        tbb::task_arena arena(2);
        return arena.execute([&] {
            Bvh bvh(scene);
            return combinedImage(render(scene, bvh));
        });
    };
    RgbaImage a = image(baked), b = image(shaded);
    Vec3f meanA(0.0f), meanB(0.0f);
    for (size_t i = 0; i + 3 < a.pixels().size(); i += 4) {
        meanA += Vec3f(a.pixels()[i], a.pixels()[i + 1], a.pixels()[i + 2]);
        meanB += Vec3f(b.pixels()[i], b.pixels()[i + 1], b.pixels()[i + 2]);
    }
    std::printf("palace in brick, mean colour baked %.4f %.4f %.4f, procedural %.4f %.4f %.4f\n", meanA.x, meanA.y,
                meanA.z, meanB.x, meanB.y, meanB.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(meanB[c], meanA[c], 0.03f * meanA[c]) << c;
    EXPECT_NE(a.pixels(), b.pixels());  // the maps do differ
}

TEST(ModularBuildings, AnUnknownMasonryIsSaidAtItsAttribute) {
    std::string message = test::inputErrorOf([] { build(R"(<render masonry="stone"/>)"); });
    EXPECT_NE(message.find("test.xml:"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown masonry 'stone' (baked, procedural)"), std::string::npos) << message;
}

// Texture-coordinate units per metre of the masonry triangles facing +x and -x (the palace's
// east and west fronts): the atlas maps each tile's metres at 1 / (texel · atlas width).
std::pair<double, double> masonryDensities(const RenderScene &scene, const Material *masonry) {
    MaterialId id = MaterialId(masonry - scene.materials.data());
    double east = 0, west = INFINITY;
    for (const BakedMesh &baked : scene.meshes) {
        const Mesh &mesh = baked.mesh;
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            if (mesh.triangleMaterials[t] != id) continue;
            const uint32_t *v = &mesh.indices[3 * t];
            Vec3f a = mesh.positions[v[0]], b = mesh.positions[v[1]], c = mesh.positions[v[2]];
            Vec3f n = cross(b - a, c - a);
            double area = 0.5 * double(length(n));
            if (area < 1e-3) continue;
            Vec2f p = mesh.uvs[v[0]], q = mesh.uvs[v[1]], r = mesh.uvs[v[2]];
            double uvArea = 0.5 * std::abs(double((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)));
            double density = std::sqrt(uvArea / area);
            if (n.x > 0.9f * length(n)) east = std::max(east, density);
            if (n.x < -0.9f * length(n)) west = std::min(west, density);
        }
    }
    return {east, west};
}

// The camera looks at the palace from the east: its west front, which the camera sees from behind,
// is baked at the coarsest texel (0.1 m), the east front as fine as the image needs (its nearest
// point 30 m off, at 640 pixels over 39.6°: about 2 cm).
TEST(ModularBuildings, AWallTheCameraSeesFromBehindTakesTheCoarsestTexel) {
    std::string xml = R"(<scene version="1"><camera position="45 8 10" look_at="14 8 10" resolution="640 360"/>
        <render masonry="baked"/><materials file="../materials/palace.xml"/>
        <modular_building structure="palace/palace.structure" style="palace/brick.style" building="7"/></scene>)";
    RenderScene scene = buildRenderScene(readSceneText(xml, "test.xml", test::sourceFile("scenes")));
    const Material *masonry = findMaterial(scene, "(building 7 masonry)");
    ASSERT_NE(masonry, nullptr);
    auto [east, west] = masonryDensities(scene, masonry);
    std::printf("texture units per metre: east %.5f, west %.5f\n", east, west);
    EXPECT_GT(east, 3 * west);
}

// Buildings are made in parallel and placed in order: the scene is the same whatever the number
// of threads, and buildings of one style share each window model as one prototype.
TEST(ModularBuildings, ThreadsChangeNothingAndWindowModelsAreShared) {
    std::string element;
    for (int i = 0; i < 4; ++i)
        element += fmt::format(R"(<modular_building structure="palace/palace.structure" style="palace/brick.style"
            building="{}" translate="{} 0 0"/>)",
                               10 + i, 60 * i);
    RenderScene one, all;
    {
        tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
        one = build(element);
    }
    all = build(element);
    ASSERT_EQ(one.meshes.size(), all.meshes.size());
    for (size_t m = 0; m < one.meshes.size(); ++m) {
        EXPECT_EQ(one.meshes[m].mesh.positions, all.meshes[m].mesh.positions) << m;
        const std::vector<Vec2f> &a = one.meshes[m].mesh.uvs, &b = all.meshes[m].mesh.uvs;
        ASSERT_EQ(a.size(), b.size());
        for (size_t v = 0; v < a.size(); ++v) ASSERT_TRUE(a[v].x == b[v].x && a[v].y == b[v].y) << m << " " << v;
        EXPECT_EQ(one.meshes[m].mesh.triangleMaterials, all.meshes[m].mesh.triangleMaterials) << m;
    }
    ASSERT_EQ(one.materials.size(), all.materials.size());
    for (size_t i = 0; i < one.materials.size(); ++i) {
        EXPECT_EQ(one.materials[i].name, all.materials[i].name);
        for (TextureId map : {one.materials[i].diffuseMap, one.materials[i].normalMap})
            if (map != kNoTexture) {
                EXPECT_EQ(one.textures->fingerprint(map), all.textures->fingerprint(map));
            }
    }
    EXPECT_EQ(one.instances.size(), all.instances.size());
    EXPECT_EQ(one.prototypes.size(), all.prototypes.size());
    // Four palaces hold no more prototypes than two (each window model is one, however many
    // buildings place it), and twice the instances.
    size_t second = element.find("/>", element.find("/>") + 2) + 2;
    RenderScene two = build(element.substr(0, second));
    EXPECT_EQ(all.prototypes.size(), two.prototypes.size());
    EXPECT_EQ(all.instances.size(), 2 * two.instances.size());
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
