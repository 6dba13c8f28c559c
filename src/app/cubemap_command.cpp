// `veduta cubemap`: converting environment maps between lat-long images, six face images and
// cross images, in the orientation the renderer reads them.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/run_guarded.h"
#include "app/scene_loading.h"
#include "assembly/build_environment.h"
#include "assembly/build_scene.h"
#include "io/cubemap_files.h"
#include "scene/cubemap_layout.h"

namespace veduta {

namespace {

struct CubemapOptions {
    std::string input, output, layout, colorSpace;
    int size = 0;
};

const std::map<std::string, CubemapLayout> kLayouts{{"faces", CubemapLayout::Faces},
                                                    {"vertical-cross", CubemapLayout::VerticalCross},
                                                    {"horizontal-cross", CubemapLayout::HorizontalCross},
                                                    {"latlong", CubemapLayout::LatLong}};

CubemapLayout outputLayout(const CubemapOptions &o) {
    if (o.layout.empty()) return isFacePattern(o.output) ? CubemapLayout::Faces : CubemapLayout::VerticalCross;
    CubemapLayout layout = kLayouts.at(o.layout);
    if ((layout == CubemapLayout::Faces) != isFacePattern(o.output)) {
        throw CLI::ValidationError("--to", "six faces need {face} or {axis} in the output name, and only they");
    }
    return layout;
}

// What a scene's environment shows, turned and scaled as the renderer sees it, sampled at
// each texel's centre: how a baked sky leaves veduta for other renderers.
Cubemap sceneEnvironment(const std::string &sceneFile, int size) {
    SceneDescription description = loadSceneDescription(sceneFile);
    if (description.environment.sky && size > 0) description.environment.faceSize = size;  // baked at the size asked
    Environment environment = buildEnvironment(description.environment, placeSun(description));
    if (!environment.cubemap) {
        throw InputError(description.environment.loc.line ? description.environment.loc : FileLoc{sceneFile},
                         "the scene's environment is a constant radiance, not a map");
    }
    Cubemap cubemap(size > 0 ? size : environment.cubemap->size());
    for (int face = 0; face < kCubeFaceCount; ++face) {
        for (int y = 0; y < cubemap.size(); ++y) {
            for (int x = 0; x < cubemap.size(); ++x) {
                Vec3f d = cubemap.direction(face, float(x) + 0.5f, float(y) + 0.5f);
                cubemap.texel(face, x, y) = environment.radianceTowards(d);
            }
        }
    }
    return cubemap;
}

void runCubemap(const CubemapOptions &o, CubemapLayout layout) {
    Cubemap cubemap;
    if (std::filesystem::path(o.input).extension() == ".xml") {
        cubemap = sceneEnvironment(o.input, o.size);
    } else {
        try {
            cubemap = readCubemap(o.input, o.colorSpace, o.size);
        } catch (const LayoutError &error) {
            throw InputError(FileLoc{o.input}, error.what());
        }
    }
    // A face size asked for resamples cube inputs too, through a fine lat-long image.
    if (o.size > 0 && cubemap.size() != o.size) {
        cubemap = cubemapFromLatLong(latLongFromCubemap(cubemap, 4 * std::max(cubemap.size(), o.size)), o.size);
    }
    writeCubemap(cubemap, o.output, layout);
    std::printf("%s: %dx%d faces\n", o.output.c_str(), cubemap.size(), cubemap.size());
}

}  // namespace

void addCubemapCommand(CLI::App &app, int &exitCode) {
    auto o = std::make_shared<CubemapOptions>();
    CLI::App *cmd = app.add_subcommand(
        "cubemap", "Convert an environment map between lat-long, six faces and a cross (see docs/cubemap.md)");
    cmd->add_option("input", o->input,
                    "Lat-long image (2:1), cross image (3:4 or 4:3), six faces: a name with {face} "
                    "(east, west, north, south, up, down) or {axis} (+x, -x, +y, -y, +z, -z), or a scene "
                    "file (.xml), whose environment (such as its baked sky) is written")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output image, or a name with {face} or {axis} for six faces")
        ->required();
    std::string layouts;
    for (const auto &[name, layout] : kLayouts) layouts += (layouts.empty() ? "" : ", ") + name;
    cmd->add_option("--to", o->layout,
                    fmt::format("Output layout: {} (default: faces for a {{face}} name, else vertical-cross)", layouts))
        ->check(CLI::IsMember(kLayouts));
    cmd->add_option("--size", o->size, "Face size in pixels (default: the input's; a lat-long image is 4x as wide)")
        ->check(CLI::Range(1, 16384));
    cmd->add_option("--colorspace", o->colorSpace,
                    "OpenColorIO colour space of the input "
                    "(default: the file's own: sRGB for 8-bit, linear for float)");
    cmd->callback([o, &exitCode] {
        CubemapLayout layout = outputLayout(*o);  // a usage error, before any work
        exitCode = runGuarded([&] { runCubemap(*o, layout); });
    });
}

}  // namespace veduta
