// Rendering with the materials-and-lights model: white furnaces with Phong and normal-mapped
// materials, sunlight through glass and past cut-outs, cubemap lighting, and the three light
// sampling strategies agreeing.
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "film/passes.h"
#include "render/bsdf.h"
#include "render/renderer.h"
#include "scene/tangents.h"
#include "test_scenes.h"

namespace veduta {
namespace {

// Textures computed from (u, v), so that tests need no image files.
class ProceduralTextures : public Textures {
  public:
    ProceduralTextures(int channels, std::function<void(Vec2f, float *)> value) :
        channels_(channels), value_(std::move(value)) {}
    TextureId add(const std::filesystem::path &, const std::string &) override { return 0; }
    TextureId add(Image) override { return 0; }
    TextureId add(std::shared_ptr<const ProceduralTexture>) override { return 0; }
    int channels(TextureId) const override { return channels_; }
    std::string fingerprint(TextureId) const override { return "procedural"; }
    void lookup(TextureId, Vec2f uv, float, float *out, int count) const override {
        float v[4] = {0, 0, 0, 0};
        value_(uv, v);
        for (int c = 0; c < count && c < channels_; ++c) out[c] = v[c];
    }

  private:
    int channels_;
    std::function<void(Vec2f, float *)> value_;
};

RgbaImage renderScene(const RenderScene &scene) {
    tbb::task_arena arena(2);
    return arena.execute([&] {
        Bvh bvh(scene);
        return combinedImage(render(scene, bvh));
    });
}

// Mean of the R, G and B values of all pixels.
double meanRgb(const RgbaImage &film) {
    double sum = 0;
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        if (i % 4 != 3) sum += film.pixels()[i];
    }
    return sum / double(film.pixels().size() / 4 * 3);
}

float maxRgb(const RgbaImage &film) {
    float highest = 0;
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        if (i % 4 != 3) highest = std::max(highest, film.pixels()[i]);
    }
    return highest;
}

float minRgb(const RgbaImage &film) {
    float lowest = 1e30f;
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        if (i % 4 != 3) lowest = std::min(lowest, film.pixels()[i]);
    }
    return lowest;
}

// A Phong sphere with k_d + k_s = 1 in a white furnace reflects everything: the
// energy-compensated lobe does not darken at grazing angles. 256 spp: the silhouette's pixels
// gather grazing samples from ±1.5 px (Cycles' filter width), whose noise at 64 spp reaches
// 0.89 in the darkest of them; at 512 spp the darkest are above 0.96, so it is noise, not bias.
TEST(MaterialsRender, PhongWhiteFurnace) {
    for (const char *shininess : {"1", "10", "100", "1000"}) {
        SCOPED_TRACE(shininess);
        RgbaImage film = renderScene(test::sceneFromXml(std::string(R"(<scene>
  <camera position="0 -4 0" look_at="0 0 0" fov="32" resolution="32 32"/>
  <sun irradiance="0"/>
  <environment radiance="1"/>
  <render spp="256" max_depth="64"/>
  <material name="phong" diffuse="0.5" specular="1" specular_intensity="0.5" shininess=")") +
                                                        shininess + R"("/>
  <sphere radius="1" segments="128" rings="64" material="phong"/>
</scene>)"));
        std::printf("Phong furnace n=%s: image mean %.5f, darkest value %.5f\n", shininess, meanRgb(film),
                    minRgb(film));
        EXPECT_NEAR(meanRgb(film), 1.0, 0.01);
        EXPECT_GT(minRgb(film), 0.9f);
    }
}

// A white diffuse plane whose normal map tilts the shading normal by up to `tiltDegrees`
// in waves, seen from above and at a grazing angle, under a uniform white sky (or `lights`).
RgbaImage normalMappedFurnace(const std::string &camera, float tiltDegrees,
                              const std::string &lights = R"(<sun irradiance="0"/><environment radiance="1"/>)") {
    RenderScene scene = test::sceneFromXml(R"(<scene>
  )" + camera + R"(
  )" + lights + R"(
  <render spp="64" max_depth="16"/>
  <material name="white" diffuse="1"/>
  <plane size="200 200" material="white"/>
</scene>)");
    float amplitude = std::tan(radians(tiltDegrees));
    scene.textures = std::make_shared<ProceduralTextures>(3, [amplitude](Vec2f uv, float *out) {
        Vec3f n = normalize({amplitude * std::sin(7 * uv.x), amplitude * std::cos(5 * uv.y), 1});
        out[0] = n.x * 0.5f + 0.5f;
        out[1] = n.y * 0.5f + 0.5f;
        out[2] = n.z * 0.5f + 0.5f;
    });
    for (Material &m : scene.materials) m.normalMap = 0;
    for (BakedMesh &m : scene.meshes) computeTangents(m.mesh);
    return renderScene(scene);
}

TEST(MaterialsRender, NormalMappedPlaneWhiteFurnace) {
    for (float tilt : {20.0f, 45.0f, 60.0f}) {
        SCOPED_TRACE(tilt);
        RgbaImage above = normalMappedFurnace(
            R"(<camera position="0 0 10" look_at="0 0 0" up="0 1 0" fov="60" resolution="32 32"/>)", tilt);
        std::printf("normal-mapped furnace, tilt up to %.0f deg: mean from above %.5f, darkest %.5f\n", tilt,
                    meanRgb(above), minRgb(above));
        EXPECT_NEAR(meanRgb(above), 1.0, 0.01);
        RgbaImage grazing =
            normalMappedFurnace(R"(<camera position="0 -30 0.5" look_at="0 0 0" fov="20" resolution="48 16"/>)", tilt);
        double sum = 0;
        int count = 0;
        for (int y = grazing.height() / 2 + 1; y < grazing.height(); ++y) {  // the rows that see the plane
            for (int x = 0; x < grazing.width(); ++x) {
                for (int c = 0; c < 3; ++c) {
                    float v = grazing.rgba()[(size_t(y) * size_t(grazing.width()) + size_t(x)) * 4 + size_t(c)];
                    sum += v;
                    ++count;
                    // No black edges: grazing views of tilted normals keep their light.
                    ASSERT_GT(v, 0.8f) << x << "," << y;
                }
            }
        }
        std::printf("normal-mapped furnace, tilt up to %.0f deg: mean at grazing view %.5f\n", tilt, sum / count);
        EXPECT_NEAR(sum / count, 1.0, 0.01);
    }
}

// The furnace cannot tell whether the map is used at all: under a low sun it must show.
TEST(MaterialsRender, NormalMapsShadeUnderTheSun) {
    const char *camera = R"(<camera position="0 0 10" look_at="0 0 0" up="0 1 0" fov="60" resolution="32 32"/>)";
    const char *sun =
        R"(<sun azimuth="90" elevation="30" irradiance="3" angular_diameter="0"/><environment radiance="0"/>)";
    RgbaImage flat = normalMappedFurnace(camera, 0, sun), mapped = normalMappedFurnace(camera, 30, sun);
    std::printf("under a sun at 30 deg: flat plane %.4f to %.4f, normal-mapped %.4f to %.4f\n", minRgb(flat),
                maxRgb(flat), minRgb(mapped), maxRgb(mapped));
    EXPECT_LT(maxRgb(flat) - minRgb(flat), 1e-4f);
    EXPECT_GT(maxRgb(mapped) - minRgb(mapped), 0.3f * maxRgb(flat));
}

// A floor of albedo 0.5 under a vertical sun of irradiance 2 behind a large pane of glass:
// the pane passes T' = 1 − R' of the sunlight, R' = 2R/(1 + R) at normal incidence.
// The floor of albedo 0.5 seen from above, under a vertical sun of irradiance 2 and what
// `above` puts between them, direct light only; materials "grey" and "pane" (glass) exist.
std::string sunlitFloor(const std::string &above, int resolution, int spp) {
    return fmt::format(R"(<scene>
  <camera position="0 0 0.5" look_at="0 0 0" up="0 1 0" fov="20" resolution="{0} {0}"/>
  <sun direction="0 0 1" irradiance="2" angular_diameter="0.53"/>
  <environment radiance="0"/>
  <render spp="{1}" max_depth="1"/>
  <material name="grey" diffuse="0.5"/>
  <material name="pane" glass="true" ior="1.5"/>
  <plane size="1000 1000" material="grey"/>
{2}</scene>)",
                       resolution, spp, above);
}

TEST(MaterialsRender, SunlightPassesGlassByFresnel) {
    RgbaImage film =
        renderScene(test::sceneFromXml(sunlitFloor(R"(  <plane size="1000 1000" translate="0 0 1" material="pane"/>)"
                                                   "\n",
                                                   16, 16)));
    double r = 0.04, transmitted = 1 - 2 * r / (1 + r);
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        if (i % 4 == 3) continue;
        ASSERT_NEAR(film.pixels()[i], 0.5 * 2 * transmitted / M_PI, 2e-3) << i;
    }
}

// The same with light bouncing: the floor's light goes up, and the pane sends back the
// cosine-weighted mean R'_h of its reflectance, so L = ρ E T' / π / (1 − ρ R'_h). Light
// through the pane is counted once, by whichever
// strategy finds it. (BSDF sampling alone finds a small sun too rarely for a 1 % test.)
TEST(MaterialsRender, SunlightThroughGlassIsCountedOnce) {
    for (const char *sampling : {"mis", "light"}) {
        SCOPED_TRACE(sampling);
        RgbaImage film = renderScene(test::sceneFromXml(std::string(R"(<scene>
  <camera position="0 0 0.5" look_at="0 0 0" up="0 1 0" fov="20" resolution="16 16"/>
  <sun direction="0 0 1" irradiance="2" angular_diameter="5"/>
  <environment radiance="0"/>
  <render spp="256" max_depth="16" light_sampling=")") + sampling +
                                                        R"("/>
  <material name="grey" diffuse="0.5"/>
  <material name="pane" glass="true" ior="1.5"/>
  <plane size="1000 1000" material="grey"/>
  <plane size="1000 1000" translate="0 0 1" material="pane"/>
</scene>)"));
        double transmitted = thinGlassTransmittance(1, 1.5f, Vec3f(1.0f)).x, hemispherical = 0;
        constexpr int kSteps = 10000;
        for (int i = 0; i < kSteps; ++i) {
            double mu = (i + 0.5) / kSteps;
            hemispherical += 2 * mu * (1 - thinGlassTransmittance(float(mu), 1.5f, Vec3f(1.0f)).x) / kSteps;
        }
        double expected = 0.5 * 2 * transmitted / M_PI / (1 - 0.5 * hemispherical);
        EXPECT_NEAR(meanRgb(film), expected, 0.01 * expected);
    }
}

// Shadow rays weigh every pane they cross, in one occlusion query or, past what it holds,
// pane by pane: under n panes the floor gets T'^n of the sunlight. The panes are instances of
// a grey plane that an instance material makes glass (two instances, so the prototype is
// kept), and a grey roof above them all stops the sun when it is there.
TEST(MaterialsRender, ShadowRaysWeighEveryPaneTheyCross) {
    auto floorUnder = [](int panes, bool roof) {
        std::string xml = R"(  <prototype name="sheet"><plane size="1000 1000" material="grey"/></prototype>
)";
        for (int i = 0; i < panes; ++i)
            xml +=
                "  <instance prototype=\"sheet\" material=\"pane\" translate=\"0 0 " + std::to_string(1 + i) + "\"/>\n";
        if (roof) xml += "  <plane size=\"1000 1000\" translate=\"0 0 100\" material=\"grey\"/>\n";
        return meanRgb(renderScene(test::sceneFromXml(sunlitFloor(xml, 8, 4))));
    };
    double r = 0.04, pane = 1 - 2 * r / (1 + r);
    // 40 panes are more than one occlusion query holds (PassedSurfaces::kCapacity).
    for (int panes : {2, 3, 40}) {
        double expected = 0.5 * 2 * std::pow(pane, panes) / M_PI;
        EXPECT_NEAR(floorUnder(panes, false), expected, 2e-3 * expected) << panes << " panes";
        EXPECT_EQ(floorUnder(panes, true), 0.0) << panes << " panes under a roof";
    }
}

// Leaves cut out everywhere cast no shadow; nowhere cut out, a full one.
TEST(MaterialsRender, CutOutsLetLightThrough) {
    for (float alpha : {0.0f, 1.0f}) {
        RenderScene scene = test::sceneFromXml(R"(<scene>
  <camera position="0 0 0.5" look_at="0 0 0" up="0 1 0" fov="20" resolution="8 8"/>
  <sun direction="0 0 1" irradiance="2"/>
  <environment radiance="0"/>
  <render spp="4" max_depth="1"/>
  <material name="grey" diffuse="0.5"/>
  <material name="leaves"/>
  <plane size="1000 1000" material="grey"/>
  <plane size="1000 1000" translate="0 0 1" material="leaves"/>
</scene>)");
        scene.textures = std::make_shared<ProceduralTextures>(4, [alpha](Vec2f, float *out) {
            out[0] = out[1] = out[2] = 0.5f;
            out[3] = alpha;
        });
        scene.materials.back().opacityMap = 0;
        RgbaImage film = renderScene(scene);
        double expected = alpha == 0 ? 0.5 * 2 / M_PI : 0.0;
        EXPECT_NEAR(meanRgb(film), expected, 1e-3) << "alpha " << alpha;
    }
}

// A cubemap of constant radiance 1 lights a plane of albedo 0.5 like the uniform sky does,
// whichever strategy finds it.
TEST(MaterialsRender, ConstantCubemapLightsLikeAUniformSky) {
    for (const char *sampling : {"mis", "bsdf", "light"}) {
        SCOPED_TRACE(sampling);
        RenderScene scene = test::sceneFromXml(std::string(R"(<scene>
  <camera position="0 0 10" look_at="0 0 0" up="0 1 0" fov="30" resolution="16 16"/>
  <sun irradiance="0"/>
  <render spp="256" max_depth="1" light_sampling=")") +
                                               sampling + R"("/>
  <material name="grey" diffuse="0.5"/>
  <plane size="1000 1000" material="grey"/>
</scene>)");
        auto cubemap = std::make_shared<Cubemap>(8);
        for (int f = 0; f < kCubeFaceCount; ++f) {
            for (int y = 0; y < 8; ++y) {
                for (int x = 0; x < 8; ++x) cubemap->texel(f, x, y) = Vec3f(1.0f);
            }
        }
        scene.environment.cubemap = cubemap;
        EXPECT_NEAR(meanRgb(renderScene(scene)), 0.5, 0.005);
    }
}

// A sky with a small bright sun (2 × 2 texels): the three strategies estimate the same image,
// as all are unbiased. (bench/mis_error.cpp measures which has the least error.)
TEST(MaterialsRender, LightSamplingStrategiesAgree) {
    auto cubemap = std::make_shared<Cubemap>(16);
    for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                Vec3f d = cubemap->direction(f, float(x) + 0.5f, float(y) + 0.5f);
                cubemap->texel(f, x, y) = d.z > 0 ? Vec3f(0.3f, 0.4f, 0.6f) : Vec3f(0.1f);
            }
        }
    }
    for (int y = 4; y < 6; ++y) {
        for (int x = 5; x < 7; ++x) cubemap->texel(kSouth, x, y) = Vec3f(300.0f);  // a sun low in the south-west
    }
    double means[3];
    int i = 0;
    for (const char *sampling : {"mis", "bsdf", "light"}) {
        RenderScene scene = test::sceneFromXml(std::string(R"(<scene>
  <camera position="0 -8 3" look_at="0 0 0.5" fov="40" resolution="24 16"/>
  <sun irradiance="0"/>
  <render spp="1024" max_depth="3" light_sampling=")") +
                                               sampling + R"("/>
  <material name="grey" diffuse="0.5"/>
  <material name="glossy" diffuse="0.3" specular="1" specular_intensity="0.4" shininess="50"/>
  <plane size="40 40" material="grey"/>
  <box size="2 2 2" rotate="0 0 30" material="glossy"/>
</scene>)");
        scene.environment.cubemap = cubemap;
        means[i++] = meanRgb(renderScene(scene));
    }
    std::printf("image means: MIS %.4f, BSDF only %.4f, light only %.4f\n", means[0], means[1], means[2]);
    EXPECT_NEAR(means[1], means[0], 0.03 * means[0]);
    EXPECT_NEAR(means[2], means[0], 0.01 * means[0]);
}

}  // namespace
}  // namespace veduta
