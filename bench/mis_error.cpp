// What multiple importance sampling gains: a diffuse scene lit by an HDR cubemap with a sun
// in it (a clear sky gradient and a 0.5°-wide disc of radiance 5·10⁴, both in the map; no
// analytic sun), rendered at 64 spp with MIS, with BSDF sampling only and with environment
// sampling only, each compared with a 4096-spp MIS reference by relMSE (pbrt's and Mitsuba's
// measure: mean over pixels and channels of (x − ref)² / (ref² + 10⁻²)). Prints the three
// figures; the acceptance of the materials-and-lights issue asks MIS to be lowest.
//
//   build/release/bench/bench_mis_error [--spp 64] [--reference-spp 4096] [--hdri FILE]
//
// With --hdri, the map is that image instead (lat-long, cross or {face} names, read through
// the image plugin: set VEDUTA_IMAGE_PLUGIN=build/release/src/veduta-images.so), e.g.
// ../shared/data/hdri/sunset.exr, a real sky with the sun in it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "assembly/build_scene.h"
#include "film/passes.h"
#include "io/cubemap_files.h"
#include "rel_mse.h"
#include "render/renderer.h"

namespace veduta {
namespace {

// A sky: brighter and bluer overhead, a grey ground, and a sun disc of 0.5° at azimuth 220°,
// elevation 25°, painted into the texels it covers.
std::shared_ptr<Cubemap> skyWithSun(int size) {
    auto map = std::make_shared<Cubemap>(size);
    Vec3f sun = Sun::directionFromAzimuthElevation(220, 25);
    float cosRadius = std::cos(radians(0.25f));
    constexpr int kSub = 4;  // sub-samples per texel side, so the small disc is area-weighted
    for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                Vec3f sum(0.0f);
                for (int i = 0; i < kSub; ++i) {
                    for (int j = 0; j < kSub; ++j) {
                        float a = float(x) + (float(i) + 0.5f) / kSub, b = float(y) + (float(j) + 0.5f) / kSub;
                        Vec3f d = map->direction(f, a, b);
                        Vec3f radiance = d.z > 0 ? Vec3f(0.25f, 0.35f, 0.6f) * (0.6f + 0.4f * d.z) : Vec3f(0.08f);
                        if (dot(d, sun) > cosRadius) radiance = Vec3f(5e4f, 4.6e4f, 4e4f);
                        sum += radiance;
                    }
                }
                map->texel(f, x, y) = sum / float(kSub * kSub);
            }
        }
    }
    return map;
}

RenderScene makeScene(LightSampling sampling, uint32_t spp, const std::shared_ptr<Cubemap> &sky) {
    SceneDescription d = readSceneText(R"(<scene>
  <camera position="-4 -14 5" look_at="1 0 1" fov="45" resolution="96 54"/>
  <sun irradiance="0"/>
  <render max_depth="4" seed="7"/>
  <material name="ground" diffuse="0.4 0.38 0.35"/>
  <material name="plaster" diffuse="0.8 0.75 0.65"/>
  <material name="red" diffuse="0.7 0.15 0.1"/>
  <plane size="60 60" material="ground"/>
  <box size="4 4 5" translate="2 2 0" material="plaster"/>
  <box size="2 6 2" translate="-3 1 0" rotate="0 0 20" material="red"/>
  <sphere radius="1" translate="0 -4 1" material="plaster"/>
</scene>)",
                                       "mis-scene", ".");
    d.settings.samplesPerPixel = spp;
    d.settings.lightSampling = sampling;
    RenderScene scene = buildRenderScene(d);
    scene.environment.cubemap = sky;
    return scene;
}

RgbaImage renderScene(const RenderScene &scene) {
    Bvh bvh(scene);
    return combinedImage(render(scene, bvh));
}

}  // namespace
}  // namespace veduta

int main(int argc, char **argv) {
    using namespace veduta;
    uint32_t spp = 64, referenceSpp = 4096;
    const char *hdri = nullptr;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--spp") == 0) spp = uint32_t(std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--reference-spp") == 0) referenceSpp = uint32_t(std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--hdri") == 0) hdri = argv[i + 1];
    }
    std::shared_ptr<Cubemap> sky = hdri ? std::make_shared<Cubemap>(readCubemap(hdri, "", 128)) : skyWithSun(64);
    RgbaImage reference = renderScene(makeScene(LightSampling::Mis, referenceSpp, sky));
    std::printf("diffuse scene lit by %s; %u spp against a %u-spp MIS reference\n",
                hdri ? hdri : "an HDR cubemap (6x64^2) with a 0.5 deg sun in it", spp, referenceSpp);
    std::printf("%-28s %12s\n", "strategy", "relMSE");
    for (auto [name, sampling] :
         {std::pair{"MIS (power heuristic)", LightSampling::Mis}, std::pair{"BSDF sampling only", LightSampling::Bsdf},
          std::pair{"environment sampling only", LightSampling::Light}}) {
        RenderScene scene = makeScene(sampling, spp, sky);
        scene.settings.seed = 1;  // independent of the reference's samples
        std::printf("%-28s %12.6f\n", name, relMse(renderScene(scene), reference));
    }
    return 0;
}
