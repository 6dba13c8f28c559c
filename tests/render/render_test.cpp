#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "app/scene_loading.h"
#include "film/passes.h"
#include "render/renderer.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

RgbaImage renderWith(const RenderScene &scene, int threads) {
    tbb::task_arena arena(threads);
    return arena.execute([&] {
        Bvh bvh(scene);
        return combinedImage(render(scene, bvh));
    });
}

RgbaImage renderXml(const std::string &xml) { return renderWith(test::sceneFromXml(xml), 2); }

// An example scene at a small size, for tests that compare renders with each other.
RenderScene exampleSceneAt(const std::string &name, int width, int height, uint32_t spp) {
    SceneDescription d = loadSceneDescription(test::sourceFile("scenes/" + name));
    d.camera.width = width;
    d.camera.height = height;
    d.settings.samplesPerPixel = spp;
    return buildRenderScene(d);
}

RenderScene defaultSceneAt(int width, int height, uint32_t spp) {
    return exampleSceneAt("default.xml", width, height, spp);
}

TEST(Render, OneAndTwoThreadsGiveBitIdenticalImages) {
    RenderScene scene = defaultSceneAt(96, 54, 4);
    RgbaImage one = renderWith(scene, 1), two = renderWith(scene, 2);
    EXPECT_EQ(one.pixels(), two.pixels());
}

// Textures, normal maps, glass, cut-outs and the cubemap environment keep the promise too.
TEST(Render, MaterialsSceneIsTheSameForAnyThreadCountAndTileSize) {
    RenderScene scene = exampleSceneAt("materials.xml", 64, 36, 2);
    RgbaImage one = renderWith(scene, 1);
    scene.settings.tileSize = 5;
    RgbaImage two = renderWith(scene, 2);
    EXPECT_EQ(one.pixels(), two.pixels());
}

TEST(Render, TileSizeDoesNotChangeTheImage) {
    RenderScene scene = defaultSceneAt(96, 54, 4);
    scene.settings.tileSize = 7;
    RgbaImage small = renderWith(scene, 2);
    scene.settings.tileSize = 64;
    RgbaImage large = renderWith(scene, 2);
    EXPECT_EQ(small.pixels(), large.pixels());
}

TEST(Render, SeedChangesTheNoiseOnly) {
    RenderScene scene = defaultSceneAt(48, 27, 2);
    RgbaImage a = renderWith(scene, 2);
    scene.settings.seed = 1;
    RgbaImage b = renderWith(scene, 2);
    EXPECT_NE(a.pixels(), b.pixels());
}

// The same two objects, once as two instances of one prototype and once as plain shapes
// that differ in their parameters, so that each is baked.
struct InstancedAndBaked {
    RenderScene instanced, baked;
};

InstancedAndBaked instancedAndBaked(int maxDepth) {
    const std::string head = R"(<scene>
  <camera position="0 -12 4" look_at="0 0 1" fov="40" resolution="96 64"/>
  <sun azimuth="200" elevation="40" irradiance="3"/>
  <environment radiance="0.4 0.5 0.7"/>
  <render spp="8" max_depth=")" +
        std::to_string(maxDepth) + R"("/>
  <material name="red" diffuse="0.8 0.2 0.1"/>
  <plane size="40 40"/>)";
    return {test::sceneFromXml(head + R"(
  <prototype name="p"><box size="1 1 2" material="red"/><sphere radius="0.6" translate="0 0 2.5"/></prototype>
  <instance prototype="p" translate="-2 0 0" rotate="0 0 30"/>
  <instance prototype="p" translate="2 1 0" scale="1.5"/>
</scene>)"),
            test::sceneFromXml(head + R"(
  <box size="1 1 2" material="red" translate="-2 0 0" rotate="0 0 30"/>
  <sphere radius="0.6" matrix="0.8660254 -0.5 0 -2  0.5 0.8660254 0 0  0 0 1 2.5"/>
  <box size="1.5 1.5 3" material="red" translate="2 1 0"/>
  <sphere radius="0.9" translate="2 1 3.75"/>
</scene>)")};
}

double mean(const RgbaImage &film) {
    double sum = 0;
    for (float v : film.pixels()) sum += v;
    return sum / double(film.pixels().size());
}

// With direct light only, every sample traces the same two rays in both scenes, and the
// only difference is float rounding in where the transform is applied.
TEST(Render, InstancedObjectsRenderLikeTheSameObjectsBaked) {
    InstancedAndBaked scenes = instancedAndBaked(1);
    ASSERT_EQ(scenes.instanced.instances.size(), 2u);
    ASSERT_EQ(scenes.baked.instances.size(), 0u);
    RgbaImage a = renderWith(scenes.instanced, 2), b = renderWith(scenes.baked, 2);
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        ASSERT_NEAR(a.pixels()[i], b.pixels()[i], 1e-5f * std::max(1.0f, a.pixels()[i])) << "value " << i;
    }
}

// With bounces, a rounding difference can send a path elsewhere and change a pixel by one
// path's worth, but never the image as a whole.
TEST(Render, InstancedAndBakedAgreeWithIndirectLight) {
    InstancedAndBaked scenes = instancedAndBaked(4);
    RgbaImage a = renderWith(scenes.instanced, 2), b = renderWith(scenes.baked, 2);
    EXPECT_NEAR(mean(a), mean(b), 1e-3 * mean(b));
}

// A white furnace: no sun, a uniform sky of radiance 1 and white (albedo 1) geometry, which
// must then be invisible.
RgbaImage renderFurnace(const std::string &camera, const std::string &settings, const std::string &geometry) {
    return renderXml("<scene>\n" + camera + R"(
  <sun irradiance="0"/>
  <environment radiance="1"/>
  <material name="white" diffuse="1"/>
  )" + settings + "\n" +
                     geometry + "\n</scene>");
}

TEST(Render, WhiteFurnace) {
    RgbaImage film = renderFurnace(R"(<camera position="0 -4 0" look_at="0 0 0" fov="40" resolution="48 48"/>)",
                                   R"(<render spp="16" max_depth="64"/>)",
                                   R"(<sphere radius="1" segments="128" rings="64" material="white"/>)");
    for (size_t i = 0; i < film.pixels().size(); ++i) ASSERT_NEAR(film.pixels()[i], 1.0f, 0.01f) << "value " << i;
}

// A corner of boxes on a plane, in which paths bounce many times, of one material "m".
RenderScene cornerScene(const std::string &lights, const std::string &albedo, const std::string &render) {
    return test::sceneFromXml(R"(<scene>
  <camera position="3 -5 4" look_at="0 0 0.5" fov="50" resolution="16 16"/>
  )" + lights + R"(
  <material name="m" diffuse=")" +
                              albedo +
                              R"("/>
  )" + render + R"(
  <plane size="6 6" material="m"/>
  <box size="1 1 1" material="m"/>
  <box size="0.4 3 2" translate="-0.8 0 0" material="m"/>
  <box size="3 0.4 2" translate="0 0.9 0" material="m"/>
</scene>)");
}

double meanRgb(const RgbaImage &film) {
    double sum = 0;
    for (size_t i = 0; i < film.pixels().size(); ++i) sum += i % 4 == 3 ? 0 : film.pixels()[i];
    return sum / double(film.pixels().size() * 3 / 4);
}

// The same in the corner, with a roulette made to decide: white surfaces keep the throughput
// at 1, which the default rule never thins out, so here every path goes on past its third
// bounce with probability 0.8 only, and then carries 1.25. Still radiance 1 in expectation.
// Per-sample values are 0 or 1.25, σ = 0.5, so pixels carry σ ≈ 0.008 at 4096 spp; the image
// mean (256 pixels) is far tighter.
TEST(Render, WhiteFurnaceWithRussianRoulette) {
    RenderScene scene = cornerScene(R"(<sun irradiance="0"/><environment radiance="1"/>)", "1",
                                    R"(<render spp="4096" max_depth="1024"/>)");
    scene.settings.roulette = {3, 1.25f};
    RgbaImage film = renderWith(scene, 2);
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        if (i % 4 != 3) {
            ASSERT_NEAR(film.pixels()[i], 1.0f, 0.05f) << "value " << i;
        }
    }
    EXPECT_NEAR(meanRgb(film), 1.0, 0.005);
}

// The default rule where it decides: grey surfaces (albedo 0.5) in the corner drop the
// throughput below its threshold after a few bounces. The image mean with roulette matches
// the one without (both 2048 spp, other seeds) to 0.5 %.
TEST(Render, RussianRouletteKeepsTheMeanOfAGreyScene) {
    auto grey = [](Roulette roulette, uint32_t seed) {
        RenderScene scene =
            cornerScene(R"(<sun azimuth="200" elevation="40" irradiance="3"/><environment radiance="0.4"/>)", "0.5",
                        R"(<render spp="2048" max_depth="64"/>)");
        scene.settings.roulette = roulette;
        scene.settings.seed = seed;
        return meanRgb(renderWith(scene, 2));
    };
    double with = grey(Roulette{}, 1), without = grey(Roulette{1u << 30, 1}, 2);
    std::printf("grey scene mean: %.5f with roulette, %.5f without\n", with, without);
    EXPECT_NEAR(with / without, 1.0, 0.005);
}

// A black sphere far behind the plane in focus, before a white sky, images as a disc of
// the thin-lens diameter A·|d − s| / (d · s · p) pixels (A the aperture, s and d the distances
// of focus and sphere, p a pixel's width one metre ahead). Its darkening's variance along x is
// that of the disc, (D/2)²/4, plus the sphere's own image's and the box filter's (1/12).
TEST(Render, DefocusedPointImagesAsTheThinLensDisc) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 0 0" look_at="0 1 0" fov="40" resolution="96 96" f_number="1" focus_distance="0.25"/>
  <sun irradiance="0"/>
  <environment radiance="1"/>
  <render spp="1024" max_depth="1" filter="box" filter_width="1"/>
  <material name="black" diffuse="0"/>
  <sphere radius="0.5" segments="256" rings="128" translate="0 20 0" material="black"/>
</scene>)");
    RgbaImage film = renderWith(scene, 2);
    const Camera &c = scene.camera;
    const float pixel = 2 * std::tan(radians(20.0f)) / 96, s = 0.25f, d = 20;
    const double expected = 2 * c.apertureRadius() * (d - s) / (d * s * pixel);
    double sum = 0, sumX = 0, sumXX = 0;
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            double w = 1 - film.rgba()[(size_t(y) * 96 + size_t(x)) * 4];
            double px = x + 0.5;
            sum += w, sumX += w * px, sumXX += w * px * px;
        }
    }
    const double sphereRadius = 0.5 / std::sqrt(d * d - 0.25) / pixel;  // its silhouette's
    double variance = sumXX / sum - (sumX / sum) * (sumX / sum);
    double diameter = 4 * std::sqrt(variance - sphereRadius * sphereRadius / 4 - 1.0 / 12);
    std::printf("defocus disc: %.2f px, thin lens %.2f px; darkening %.3f px², sphere %.3f px²\n", diameter, expected,
                sum, kPi * sphereRadius * sphereRadius);
    ASSERT_GT(expected, 20);  // the disc is large against the sphere and the filter
    EXPECT_NEAR(diameter, expected, 0.02 * expected);
    // The sphere's darkening is spread, not lost: its image keeps the sphere's area.
    EXPECT_NEAR(sum, kPi * sphereRadius * sphereRadius, 0.03 * kPi * sphereRadius * sphereRadius);
}

// Aerial perspective is energy-neutral in a furnace: white surfaces under a uniform sky of 1,
// seen through thick fog whose glow is taken from that sky, still have radiance 1, as does the
// sky itself; with a black sky and no sun the fog adds nothing.
TEST(Render, FogInAWhiteFurnaceKeepsRadianceOne) {
    const char *scene = R"(<scene>
  <camera position="0 -30 3" look_at="0 0 2" fov="60" resolution="32 24"/>
  <sun irradiance="0"/>
  <environment radiance="%s"/>
  <fog density="0.05" height="0" scale_height="20"/>
  <material name="white" diffuse="1"/>
  <render spp="64" max_depth="64"/>
  <ground material="white"/>
  <box size="4 4 6" material="white"/>
  <sphere radius="2" translate="6 5 2" material="white"/>
</scene>)";
    char xml[1024];
    std::snprintf(xml, sizeof xml, scene, "1");
    RenderScene furnace = test::sceneFromXml(xml);
    EXPECT_NEAR(furnace.fog.inscatter.x, 1.0f, 1e-3f);
    RgbaImage film = renderWith(furnace, 2);
    for (size_t i = 0; i < film.pixels().size(); ++i) ASSERT_NEAR(film.pixels()[i], 1.0f, 0.01f) << "value " << i;
    std::snprintf(xml, sizeof xml, scene, "0");
    RgbaImage dark = renderXml(xml);
    for (size_t i = 0; i < dark.pixels().size(); ++i) {
        if (i % 4 != 3) {
            ASSERT_EQ(dark.pixels()[i], 0.0f) << "value " << i;
        }
    }
}

// The endless ground leaves no sky below the horizon, however far the scene's own ground ends:
// a black ground before a white sky, seen level from 2 m, is black in every row below the
// middle; without it, the lower half is sky.
TEST(Render, GroundReachesTheHorizon) {
    auto lowerHalfMax = [](const char *ground) {
        RgbaImage film = renderXml(std::string(R"(<scene>
  <camera position="0 0 2" look_at="0 100 2" fov="40" resolution="64 64"/>
  <sun irradiance="0"/>
  <environment radiance="1"/>
  <material name="black" diffuse="0"/>
  <render spp="4" max_depth="2"/>
  <plane size="100 100" material="black"/>
  )") + ground + "\n</scene>");
        float brightest = 0;
        for (int y = 35; y < 64; ++y) {  // below the filter's reach of the horizon row
            for (int x = 0; x < 64; ++x) brightest = std::max(brightest, film.rgba()[(size_t(y) * 64 + size_t(x)) * 4]);
        }
        return brightest;
    };
    EXPECT_EQ(lowerHalfMax(R"(<ground height="-0.01" material="black"/>)"), 0.0f);
    EXPECT_GT(lowerHalfMax(""), 0.5f);
}

// A Lambertian plane of albedo ρ lit by a sun of irradiance E at incidence θ, with a black
// sky, has radiance ρ·E·cos θ / π everywhere.
void expectPlaneRadiance(const std::string &sun, float expected) {
    RgbaImage film = renderXml(R"(<scene>
  <camera position="0 0 10" look_at="0 0 0" up="0 1 0" fov="30" resolution="32 32"/>
  )" + sun + R"(
  <environment radiance="0"/>
  <render spp="16" max_depth="8"/>
  <material name="grey" diffuse="0.5"/>
  <plane size="1000 1000" material="grey"/>
</scene>)");
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            for (int c = 0; c < 3; ++c) {
                float v = film.rgba()[(size_t(y) * size_t(film.width()) + size_t(x)) * 4 + size_t(c)];
                ASSERT_NEAR(v, expected, 0.01f * expected) << "pixel " << x << "," << y;
            }
        }
    }
}

TEST(Render, AnalyticPlaneUnderSunAtNormalIncidence) {
    expectPlaneRadiance(R"(<sun direction="0 0 1" irradiance="2" angular_diameter="0.53"/>)", 0.5f * 2.0f / kPi);
}

// Small discs too: their cone must not collapse in float precision.
TEST(Render, AnalyticPlaneUnderSmallSuns) {
    for (const char *diameter : {"0.01", "0.02", "0.05", "0.1"}) {
        SCOPED_TRACE(diameter);
        expectPlaneRadiance(
            std::string(R"(<sun direction="0 0 1" irradiance="2" angular_diameter=")") + diameter + "\"/>",
            0.5f * 2.0f / kPi);
    }
}

TEST(Render, AnalyticPlaneUnderSunAtSixtyDegrees) {
    expectPlaneRadiance(R"(<sun azimuth="30" elevation="30" irradiance="2" angular_diameter="0"/>)",
                        0.5f * 2.0f * 0.5f / kPi);
}

// Under a uniform sky of radiance 1 and nothing else, a plane of albedo ρ reflects ρ.
TEST(Render, AnalyticPlaneUnderUniformSky) {
    RgbaImage film = renderXml(R"(<scene>
  <camera position="0 0 10" look_at="0 0 0" up="0 1 0" fov="30" resolution="32 32"/>
  <sun irradiance="0"/>
  <environment radiance="1"/>
  <render spp="16" max_depth="8"/>
  <material name="grey" diffuse="0.5"/>
  <plane size="1000 1000" material="grey"/>
</scene>)");
    for (size_t i = 0; i < film.pixels().size(); ++i) ASSERT_NEAR(film.pixels()[i], i % 4 == 3 ? 1.0f : 0.5f, 0.005f);
}

TEST(Render, BuiltInDefaultSceneParsesAndHasInstances) {
    RenderScene scene = buildRenderScene(loadSceneDescription(""));
    EXPECT_GT(scene.instances.size(), 10u);
    EXPECT_GT(scene.meshes.size(), 3u);
}

}  // namespace
}  // namespace veduta
