// The film as renders fill it: regions, passes and resumed renders give exactly the pixels of
// one uninterrupted full render; the passes hold what their names say.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include <tbb/task_arena.h>

#include "film/passes.h"
#include "io/checkpoint_file.h"
#include "render/renderer.h"
#include "scene/scene_hash.h"
#include "test_scenes.h"

namespace veduta {
namespace {

RenderScene smallDefaultScene(float noiseThreshold = 0) {
    SceneDescription d = test::defaultSceneAt(64, 36, 24);
    d.settings.noiseThreshold = noiseThreshold;
    d.settings.minSamples = 8;
    return buildRenderScene(d);
}

LayeredImage renderDeveloped(const RenderScene &scene, const Bvh &bvh, const RenderOptions &options) {
    return tbb::task_arena(2).execute([&] { return developFilm(render(scene, bvh, options)); });
}

// Every channel of `part` equals the same pixels of `whole`, bit for bit.
void expectSamePixels(const LayeredImage &whole, const LayeredImage &part) {
    const PixelWindow &w = part.dataWindow;
    for (const LayeredImage::Channel &c : part.channels) {
        const LayeredImage::Channel *full = whole.find(c.name);
        ASSERT_NE(full, nullptr) << c.name;
        size_t mismatches = 0;
        for (int y = w.y0; y < w.y1; ++y) {
            for (int x = w.x0; x < w.x1; ++x) {
                float a = full->values[size_t(y) * size_t(whole.dataWindow.width()) + size_t(x)];
                float b = c.values[size_t(y - w.y0) * size_t(w.width()) + size_t(x - w.x0)];
                if (std::memcmp(&a, &b, sizeof a) != 0) ++mismatches;
            }
        }
        EXPECT_EQ(mismatches, 0u) << c.name;
    }
}

class FilmRegions : public testing::TestWithParam<float> {};

TEST_P(FilmRegions, FourRegionsAreBitIdenticalToTheFullRender) {
    RenderScene scene = smallDefaultScene(GetParam());
    Bvh bvh(scene);
    LayeredImage whole = renderDeveloped(scene, bvh, {});
    for (PixelWindow region : {PixelWindow{0, 0, 30, 20}, PixelWindow{30, 0, 64, 20}, PixelWindow{0, 20, 30, 36},
                               PixelWindow{30, 20, 64, 36}}) {
        RenderOptions options;
        options.region = region;
        LayeredImage part = renderDeveloped(scene, bvh, options);
        EXPECT_EQ(part.dataWindow, region);
        EXPECT_EQ(part.fullWidth, 64);
        expectSamePixels(whole, part);
    }
}

// Uniform sampling, and adaptive sampling whose per-pixel decisions a region must repeat.
INSTANTIATE_TEST_SUITE_P(UniformAndAdaptive, FilmRegions, testing::Values(0.0f, 0.05f));

TEST(Film, PassSizeDoesNotChangeTheImage) {
    RenderScene scene = smallDefaultScene();
    Bvh bvh(scene);
    RenderOptions onePass, manyPasses;
    manyPasses.passSamples = 1;
    int passes = 0;
    manyPasses.afterPass = [&](Film &, const RenderStats &) { ++passes; };
    expectSamePixels(renderDeveloped(scene, bvh, onePass), renderDeveloped(scene, bvh, manyPasses));
    EXPECT_EQ(passes, 24);
}

TEST(Film, ResumingFromACheckpointContinuesExactly) {
    for (float threshold : {0.0f, 0.05f}) {
        RenderScene scene = smallDefaultScene(threshold);
        Bvh bvh(scene);
        std::filesystem::path file = testing::TempDir() + "film_test.checkpoint";
        RenderIdentity identity{{"scene", hashText(sceneHash(scene))}};
        RenderOptions options;
        options.passSamples = 4;
        options.afterPass = [&](Film &film, const RenderStats &stats) {
            if (stats.samplesDone == 12) writeCheckpoint(file, identity, film, stats);
        };
        LayeredImage whole = renderDeveloped(scene, bvh, options);

        Film film = makeFilm(scene, {});
        RenderStats stats;
        readCheckpoint(file, identity, film, stats);
        EXPECT_EQ(stats.samplesDone, 12u);
        tbb::task_arena(1).execute([&] { renderFilm(scene, bvh, {}, film, stats); });
        expectSamePixels(whole, developFilm(film));
        std::filesystem::remove(file);
    }
}

TEST(Film, TimeLimitStopsAfterAPassWithAWholeImage) {
    RenderScene scene = smallDefaultScene();
    scene.settings.samplesPerPixel = 1u << 20;
    Bvh bvh(scene);
    RenderOptions options;
    options.timeLimitSeconds = 0.3;
    RenderStats stats;
    Film film = render(scene, bvh, options, &stats);
    EXPECT_LT(stats.seconds, 2.0);
    EXPECT_GT(stats.samplesDone, 0u);
    for (size_t p = 0; p < film.pixelCount(); ++p) ASSERT_EQ(film.sampleCount(p), stats.samplesDone);
}

TEST(FilmPasses, HoldDepthNormalAlbedoPositionAndIds) {
    RenderScene scene = test::sceneFromXml(R"(<scene version="1">
  <camera position="0 -10 1" look_at="0 0 1" fov="40" resolution="40 20"/>
  <render spp="4"/>
  <material name="red" diffuse="0.6 0.1 0.1"/>
  <prototype name="post"><box size="1 1 4" material="red"/></prototype>
  <box size="2 0.5 2" translate="-3 0 0" material="red" id="5" building="77"/>
  <instance prototype="post" translate="3 0 0" id="9" building="78"/>
  <instance prototype="post" translate="30 0 0"/>
</scene>)");
    LayeredImage image = developFilm(render(scene, Bvh(scene)));
    auto at = [&](const char *pass, const char *channel, int x, int y) {
        return image.find(passChannel(pass, channel))->values[size_t(y) * 40 + size_t(x)];
    };
    // Pixel (12, 10) looks at the box's front face at y = −0.25, x ≈ −3; (28, 10) at the post.
    EXPECT_EQ(at("IndexOB", "X", 12, 10), 5.0f);
    EXPECT_EQ(at("IndexBuilding", "X", 12, 10), 77.0f);
    EXPECT_EQ(at("IndexInstance", "X", 12, 10), 0.0f);
    EXPECT_EQ(at("IndexOB", "X", 28, 10), 9.0f);
    EXPECT_EQ(at("IndexBuilding", "X", 28, 10), 78.0f);
    EXPECT_EQ(at("IndexInstance", "X", 28, 10), 1.0f);
    EXPECT_EQ(at("IndexMA", "X", 12, 10), 2.0f);  // "red" after "default"
    EXPECT_NEAR(at("Depth", "Z", 12, 10), 9.75f, 1e-3f);
    EXPECT_NEAR(at("Position", "Y", 12, 10), -0.25f, 1e-4f);
    EXPECT_NEAR(at("Normal", "Y", 12, 10), -1.0f, 1e-5f);
    EXPECT_NEAR(at("DiffCol", "R", 12, 10), 0.6f, 1e-6f);
    EXPECT_NEAR(at("DiffCol", "G", 12, 10), 0.1f, 1e-6f);
    // The sky: Blender's background depth, no ids, no albedo.
    EXPECT_EQ(at("Depth", "Z", 20, 0), kBackgroundDepth);
    EXPECT_EQ(at("IndexOB", "X", 20, 0), 0.0f);
    EXPECT_EQ(at("DiffCol", "R", 20, 0), 0.0f);
    EXPECT_EQ(at("SampleCount", "X", 20, 0), 4.0f);
    EXPECT_EQ(at("Combined", "A", 20, 0), 1.0f);
}

TEST(FilmPasses, HalfBuffersAverageToTheCombinedPass) {
    RenderScene scene = smallDefaultScene();
    LayeredImage image = developFilm(render(scene, Bvh(scene)));
    const auto &all = image.find(passChannel("Combined", "G"))->values;
    const auto &even = image.find(passChannel("CombinedEven", "G"))->values;
    const auto &odd = image.find(passChannel("CombinedOdd", "G"))->values;
    double differences = 0;
    for (size_t p = 0; p < all.size(); ++p) {
        ASSERT_NEAR(0.5f * (even[p] + odd[p]), all[p], 1e-5f * (1 + all[p]));
        differences += std::abs(even[p] - odd[p]);
    }
    EXPECT_GT(differences, 0);  // two independent halves, not one copied
}

}  // namespace
}  // namespace veduta
