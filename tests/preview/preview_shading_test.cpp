// What the preview's shaded and thesis modes draw: the sun's Lambert and Phong terms and the
// sky light as closed forms, seed 000's PPSUNS (T13) through the thesis mode, the environment as
// background, and textured scenes drawn the same on any threads and tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <tbb/task_arena.h>

#include "preview/example_scenes.h"
#include "preview/preview.h"
#include "same_preview.h"
#include "test_paths.h"
#include "test_scenes.h"

namespace veduta {
namespace {

constexpr float kIrradiance = 3, kSky = 0.2f, kShininess = 20;
const Vec3f kDiffuse{0.5f, 0.4f, 0.3f};
const Vec3f kSpecular = Vec3f(1.0f, 1.0f, 0.85f) * 0.3f;  // Bilke's specular colour × intensity

// A plane of a glossy material under a sun at `elevation` degrees in the south and a uniform sky.
RenderScene glossyPlane(const std::string &camera, float elevation) {
    return test::sceneFromXml(R"(<scene>
  )" + camera + R"(
  <sun azimuth="180" elevation=")" +
                              std::to_string(elevation) +
                              R"(" irradiance="3" angular_diameter="0"/>
  <environment radiance="0.2"/>
  <material name="glossy" diffuse="0.5 0.4 0.3" specular_intensity="0.3" shininess="20"/>
  <plane size="100 100" material="glossy"/>
</scene>)");
}

void expectPixel(const RgbaImage &film, int x, int y, const Vec3f &expected) {
    const float *c = &film.rgba()[(size_t(y) * size_t(film.width()) + size_t(x)) * 4];
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(c[k], expected[k], 2e-3f * expected[k] + 1e-5f) << x << "," << y;
}

// Shaded: (k_d/π + k_s (n+2)/(2π) cosⁿα) E cos θ + (k_d + k_s) L_sky, α the angle between the
// sun and the view direction mirrored about the normal: the path tracer's diffuse and Phong lobes
// lit by the sun, with the sky's radiance on both. Seen from every pixel of a perspective view,
// so that the highlight lies where the mirror direction meets the sun.
TEST(PreviewShading, ShadedModeIsLambertPlusPhongUnderTheSunAndSky) {
    const float elevation = 35;
    RenderScene scene =
        glossyPlane(R"(<camera position="0 20 6" look_at="0 0 0" up="0 0 1" fov="60" resolution="48 32"/>)", elevation);
    RgbaImage film = renderPreview(scene, PreviewOptions{}).film;
    CameraRays rays(scene.camera);
    const Vec3f n{0, 0, 1}, sun = scene.sun.direction;
    float brightest = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 48; ++x) {
            Ray r = rays.generate(float(x) + 0.5f, float(y) + 0.5f);
            if (r.direction.z > -1e-3f) continue;  // the sky
            Vec3f hit = r.origin - r.direction * (r.origin.z / r.direction.z);
            if (std::abs(hit.x) > 49 || std::abs(hit.y) > 49) continue;  // beyond the plane
            Vec3f toEye = -r.direction;
            Vec3f mirrored = n * (2 * dot(n, toEye)) - toEye;
            float lobe = (kShininess + 2) / (2 * kPi) * std::pow(std::max(dot(mirrored, sun), 0.0f), kShininess);
            float cosine = dot(n, sun);
            Vec3f expected =
                (kDiffuse * kInvPi + kSpecular * lobe) * kIrradiance * cosine + (kDiffuse + kSpecular) * kSky;
            expectPixel(film, x, y, expected);
            brightest = std::max(brightest, lobe);
        }
    }
    EXPECT_GT(brightest, 1.0f);  // the view sees the highlight
}

// T13 through the thesis mode: with the sun at the zenith and an orthographic view straight down,
// the normal, light and eye coincide (R·V = 1), and PPSUNS gives
// (0.6·La + 0.5·env + 0.325·Ld)·base + Ls·Ms, with the sun's E/π as Ld and Ls, the sky's radiance
// as La and env, k_d as base and k_s as Ms.
TEST(PreviewShading, ThesisModeIsPpsunsWithTheSunAsItsLight) {
    RenderScene scene = glossyPlane(
        R"(<camera position="0 0 10" look_at="0 0 0" up="0 1 0" projection="orthographic" ortho_scale="4" resolution="8 8"/>)",
        90);
    PreviewOptions options;
    options.mode = PreviewMode::Thesis;
    RgbaImage film = renderPreview(scene, options).film;
    float sunRadiance = kIrradiance * kInvPi;
    Vec3f expected = kDiffuse * (0.6f * kSky + 0.5f * kSky + 0.325f * sunRadiance) + kSpecular * sunRadiance;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) expectPixel(film, x, y, expected);
    }
}

// Where nothing is drawn, the shaded and thesis modes show the environment the camera ray
// through the pixel centre would see: here a cubemap, not its mean.
TEST(PreviewShading, BackgroundIsTheEnvironmentAlongEachPixelsRay) {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 0 1" look_at="0 10 3" up="0 0 1" fov="70" resolution="40 30"/>
  <sun azimuth="200" elevation="30"/>
  <environment sky="preetham"/>
  <box size="2 2 2" translate="0 8 0"/>
</scene>)");
    ASSERT_TRUE(scene.environment.cubemap);
    CameraRays rays(scene.camera);
    for (PreviewMode mode : {PreviewMode::Shaded, PreviewMode::Thesis}) {
        PreviewOptions options;
        options.mode = mode;
        PreviewImage image = renderPreview(scene, options);
        int background = 0;
        float lowest = 1e30f, highest = 0;
        for (int y = 0; y < 30; ++y) {
            for (int x = 0; x < 40; ++x) {
                if (image.objectId[size_t(y) * 40 + size_t(x)] != 0) continue;
                Vec3f sky =
                    scene.environment.radianceTowards(rays.generate(float(x) + 0.5f, float(y) + 0.5f).direction);
                expectPixel(image.film, x, y, sky);
                lowest = std::min(lowest, sky.z);
                highest = std::max(highest, sky.z);
                ++background;
            }
        }
        EXPECT_GT(background, 600);
        EXPECT_GT(highest, 1.2f * lowest);  // the sky is not one colour
    }
}

// Textures, normal maps, cut-outs and the cubemap keep the image independent of threads and
// tile size, in every mode that reads them, with every option on.
TEST(PreviewShading, TexturedSceneIsTheSameForAnyThreadsAndTiles) {
    RenderScene scene = test::exampleScene(test::sourceFile("scenes/materials.xml"), 96);
    ASSERT_TRUE(scene.textures);
    test::expectSameForAnyThreadsAndTiles(
        scene, {PreviewMode::Shaded, PreviewMode::Albedo, PreviewMode::Normal, PreviewMode::Thesis});
}

}  // namespace
}  // namespace veduta
