#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <tbb/task_arena.h>

#include "film/passes.h"
#include "preview/example_scenes.h"
#include "preview/preview.h"
#include "render/first_hits.h"
#include "render/object_ids.h"
#include "render/renderer.h"
#include "same_preview.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// The preview's silhouettes are the path tracer's: per pixel, the object hit at the pixel
// centre is the same on at least 99.5 % of pixels (edges may round either way).
TEST(Preview, ObjectIdsAgreeWithThePathTracerInEveryExampleScene) {
    std::vector<std::filesystem::path> files = test::exampleScenes();
    ASSERT_GE(files.size(), 2u);
    for (const auto &file : files) {
        SCOPED_TRACE(file.string());
        RenderScene scene = test::exampleScene(file);
        std::vector<uint32_t> traced = objectIdsAtPixelCentres(scene, Bvh(scene));
        PreviewOptions options;
        options.mode = PreviewMode::Id;
        std::vector<uint32_t> drawn = renderPreview(scene, options).objectId;
        ASSERT_EQ(traced.size(), drawn.size());
        size_t same = 0;
        for (size_t i = 0; i < traced.size(); ++i) same += traced[i] == drawn[i];
        double agreement = double(same) / double(traced.size());
        std::printf("%s: object ids agree on %.3f %% of %zu pixels\n", file.filename().c_str(), 100 * agreement,
                    traced.size());
        EXPECT_GE(agreement, 0.995) << same << " of " << traced.size();
    }
}

PreviewImage previewWith(const RenderScene &scene, int threads, int tileSize, PreviewMode mode = PreviewMode::Shaded) {
    PreviewOptions options;
    options.mode = mode;
    options.tileSize = tileSize;
    tbb::task_arena arena(threads);
    return arena.execute([&] { return renderPreview(scene, options); });
}

TEST(Preview, ThreadsAndTilesDoNotChangeTheImage) {
    RenderScene scene = test::exampleScene(test::sourceFile("scenes/default.xml"));
    PreviewImage a = previewWith(scene, 1, 64), b = previewWith(scene, 2, 64), c = previewWith(scene, 2, 13);
    EXPECT_EQ(a.film.pixels(), b.film.pixels());
    EXPECT_EQ(a.film.pixels(), c.film.pixels());
    EXPECT_EQ(a.objectId, c.objectId);
}

// The same with every option on and a camera inside geometry (clipping) and among instances.
TEST(Preview, ThreadsAndTilesDoNotChangeTheImageWithEveryOption) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 0 1" look_at="3 1 1.5" fov="90" resolution="80 60"/>
  <box size="6 6 4"/>
  <prototype name="p"><sphere radius="0.4"/><box size="0.3 0.3 1"/></prototype>
  <instance prototype="p" translate="2 0 1" scale="-1 1 1"/>
  <instance prototype="p" translate="2 1.5 1" rotate="10 20 30"/>
</scene>)");
    test::expectSameForAnyThreadsAndTiles(
        scene, {PreviewMode::Shaded, PreviewMode::Normal, PreviewMode::Depth, PreviewMode::Id});
}

// Neighbouring triangles leave no pixel centre uncovered: seen from inside a finely divided
// sphere, every pixel shows the sphere.
TEST(Preview, SharedEdgesAreWatertight) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0.3 -0.2 0.1" look_at="1 2 0.5" fov="120" resolution="200 150"/>
  <sphere radius="10" segments="512" rings="256" id="3"/>
</scene>)");
    for (uint32_t id : renderPreview(scene, PreviewOptions{}).objectId) ASSERT_EQ(id, 3u);
}

// Attributes are interpolated perspective-correctly: the preview's normals match the path
// tracer's normal pass (its interpolated shading normals, turned where they would mirror the view
// below the surface) at each pixel centre, even on large triangles seen at a slant, where
// screen-space (affine) interpolation would be visibly off.
TEST(Preview, NormalsArePerspectiveCorrect) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 -3 0.5" look_at="0 0 0" fov="60" resolution="96 96"/>
  <sphere radius="1.5" segments="8" rings="6"/>
</scene>)");
    PreviewOptions options;
    options.mode = PreviewMode::Normal;
    PreviewImage image = renderPreview(scene, options);
    std::vector<FirstHit> traced = firstHitsAtPixelCentres(scene, Bvh(scene));
    int compared = 0;
    for (size_t p = 0; p < traced.size(); ++p) {
        if (!traced[p].hit || image.objectId[p] == 0) continue;
        const float *c = &image.film.rgba()[p * 4];
        Vec3f drawn{c[0] * 2 - 1, c[1] * 2 - 1, c[2] * 2 - 1};
        ASSERT_GT(dot(normalize(drawn), traced[p].normal), 0.9999f) << p % 96 << "," << p / 96;
        ++compared;
    }
    EXPECT_GT(compared, 3000);
}

// Depth is interpolated perspective-correctly: on a tilted plane it matches the exact
// view-axis distance of the ray through each pixel centre.
TEST(Preview, DepthIsPerspectiveCorrect) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 -10 3" look_at="0 10 0" fov="60" resolution="64 48"/>
  <plane size="100 100"/>
</scene>)");
    PreviewImage image = previewWith(scene, 2, 16, PreviewMode::Depth);
    CameraRays rays(scene.camera);
    Vec3f forward = normalize(scene.camera.lookAt - scene.camera.position);
    int checked = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            Ray r = rays.generate(float(x) + 0.5f, float(y) + 0.5f);
            if (r.direction.z >= -1e-3f) continue;  // above the horizon
            float t = -r.origin.z / r.direction.z;
            Vec3f hit = r.origin + r.direction * t;
            if (std::abs(hit.x) > 50 || std::abs(hit.y) > 50) continue;
            float expected = dot(hit - r.origin, forward);
            ASSERT_NEAR(image.depth[size_t(y) * 64 + size_t(x)], expected, 1e-4f * expected) << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

// The preview draws the path tracer's frame for shifted and orthographic cameras too: at each
// pixel centre its depth is the view-axis distance of the camera ray's hit on a tilted plane,
// and a box shows where the rays meet it.
TEST(Preview, ShiftedAndOrthographicFramesMatchTheCameraRays) {
    for (const char *camera : {R"(fov="60" shift="0.1 0.25")", R"(projection="orthographic" ortho_scale="30")",
                               R"(projection="orthographic" ortho_scale="30" shift="-0.2 0.1")"}) {
        SCOPED_TRACE(camera);
        RenderScene scene = test::sceneFromXml(std::string(R"(<scene>
  <camera position="2 -10 3" look_at="0 10 0" resolution="64 48" )") +
                                               camera + R"(/>
  <plane size="100 100" id="1"/>
  <box size="3 3 4" translate="1 4 0" id="2"/>
</scene>)");
        PreviewImage depth = previewWith(scene, 2, 16, PreviewMode::Depth);
        PreviewImage ids = previewWith(scene, 2, 16, PreviewMode::Id);
        Bvh bvh(scene);
        CameraRays rays(scene.camera);
        Vec3f forward = normalize(scene.camera.lookAt - scene.camera.position);
        int checked = 0, agreeing = 0, pixels = 0;
        for (int y = 0; y < 48; ++y) {
            for (int x = 0; x < 64; ++x) {
                Ray r = rays.generate(float(x) + 0.5f, float(y) + 0.5f);
                std::optional<Hit> hit = bvh.intersect(r, true);
                uint32_t expectedId = hit ? scene.meshes[hit->index].objectId : 0;
                size_t p = size_t(y) * 64 + size_t(x);
                ++pixels;
                agreeing += ids.objectId[p] == expectedId;
                if (!hit || expectedId != 1) continue;
                float expected = dot(r.origin + r.direction * hit->t - scene.camera.position, forward);
                ASSERT_NEAR(depth.depth[p], expected, 1e-3f * expected) << x << "," << y;
                ++checked;
            }
        }
        EXPECT_GT(checked, 500);
        EXPECT_GT(agreeing, pixels * 99 / 100);  // edges may fall either way
    }
}

// Geometry crossing the near plane is clipped, not dropped: from inside a box every pixel
// still shows the box.
TEST(Preview, TrianglesCrossingTheNearPlaneAreClippedNotDropped) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 0 1" look_at="1 0.3 1.2" fov="100" resolution="64 48"/>
  <box size="4 4 3" id="7"/>
</scene>)");
    PreviewImage image = previewWith(scene, 2, 16, PreviewMode::Id);
    for (uint32_t id : image.objectId) ASSERT_EQ(id, 7u);
}

TEST(Preview, BackFaceCullingHidesTheInsideOfAClosedBox) {
    const char *xml = R"(<scene>
  <camera position="0 0 1" look_at="1 0 1" fov="60" resolution="32 32"/>
  <box size="4 4 3"/>
</scene>)";
    RenderScene scene = test::sceneFromXml(xml);
    PreviewOptions options;
    options.backfaceCulling = true;
    for (uint32_t id : renderPreview(scene, options).objectId) ASSERT_EQ(id, 0u);
}

// Culling keeps the faces turned to the camera, also of mirrored instances: the near face
// of each box is what the centre of its half of the image shows.
TEST(Preview, BackFaceCullingKeepsFrontFacesOfMirroredInstances) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 -10 1" look_at="0 0 1" fov="40" resolution="64 32"/>
  <prototype name="p"><box size="2 2 2"/></prototype>
  <instance prototype="p" translate="-1.5 0 0" id="1"/>
  <instance prototype="p" translate="1.5 0 0" scale="-1 1 1" id="2"/>
</scene>)");
    ASSERT_EQ(scene.instances.size(), 2u);
    PreviewOptions options;
    options.backfaceCulling = true;
    PreviewImage image = renderPreview(scene, options);
    for (auto [x, id] : {std::pair{24, 1u}, std::pair{39, 2u}}) {
        size_t p = 16 * 64 + size_t(x);
        EXPECT_EQ(image.objectId[p], id);
        EXPECT_NEAR(image.depth[p], 9.0f, 1e-3f);  // the face at y = -1, not the far one at y = +1
    }
}

// The shadow map puts shadows where the path tracer finds the sun blocked: with direct light
// only, a pixel is dark in one exactly when it is dark in the other, but for pixels along
// shadow edges (under a tenth of the shadowed ones).
TEST(Preview, ShadowsAgreeWithThePathTracer) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 -2 30" look_at="0 0 0" up="0 1 0" fov="45" resolution="96 96"/>
  <sun azimuth="120" elevation="50" irradiance="3" angular_diameter="0"/>
  <environment radiance="0"/>
  <render spp="4" max_depth="1"/>
  <plane size="30 30"/>
  <box size="3 2 1" translate="-3 2 4"/>
  <sphere radius="1.5" translate="4 -3 3"/>
  <cylinder radius="0.3" height="6" translate="2 5 0"/>
</scene>)");
    PreviewOptions options;
    options.shadows = true;
    RgbaImage drawn = renderPreview(scene, options).film;
    RgbaImage traced = tbb::task_arena(2).execute([&] { return combinedImage(render(scene, Bvh(scene))); });
    // Lit ground shows ρ E cos θ / π; shadowed ground shows 0.
    float lit = 0.8f * 3.0f * std::sin(radians(50)) * kInvPi;
    size_t agree = 0, shadowedPixels = 0;
    for (int i = 0; i < 96 * 96; ++i) {
        bool dark = drawn.pixels()[size_t(i) * 4 + 1] < 0.5f * lit;
        agree += dark == (traced.pixels()[size_t(i) * 4 + 1] < 0.5f * lit);
        shadowedPixels += dark;
    }
    size_t disagree = 96 * 96 - agree;
    std::printf("shadows: %zu shadowed pixels, %zu disagree with the path tracer\n", shadowedPixels, disagree);
    EXPECT_GT(shadowedPixels, 200u);           // the test sees real shadows
    EXPECT_LE(disagree, shadowedPixels / 10);  // only along shadow edges
}

TEST(Preview, IdColoursAreDistinctAndBackgroundIsBlack) {
    EXPECT_EQ(objectIdColor(0), Vec3f(0.0f));
    for (uint32_t id = 1; id < 200; ++id) {
        EXPECT_GE(maxComponent(objectIdColor(id)), 0.1f);
        EXPECT_NE(objectIdColor(id), objectIdColor(id + 1));
    }
}

}  // namespace
}  // namespace veduta
