#include "assembly/build_environment.h"

#include <fmt/format.h>

#include "io/cubemap_files.h"
#include "scene/cubemap_layout.h"
#include "scene/sky.h"

namespace veduta {

namespace {

Cubemap loadCubemap(const EnvironmentDesc &desc) {
    const ImageRef &ref = desc.cubemap;
    try {
        return readCubemap(ref.file, ref.colorSpace, desc.faceSize);
    } catch (const LayoutError &error) {
        throw InputError(ref.loc, fmt::format("{}: {}", ref.file.string(), error.what()));
    } catch (const InputError &error) {  // the image library's errors name the file
        throw InputError(ref.loc, error.what());
    }
}

}  // namespace

Environment buildEnvironment(const EnvironmentDesc &desc, const Sun &sun) {
    Environment env;
    env.radiance = desc.radiance;
    env.rotationDegrees = desc.rotationDegrees;
    env.intensity = desc.intensity;
    if (desc.cubemap.given()) {
        env.cubemap = std::make_shared<const Cubemap>(loadCubemap(desc));
    } else if (desc.sky) {
        SkySettings settings;
        settings.turbidity = desc.turbidity;
        settings.groundAlbedo = desc.groundAlbedo;
        if (desc.faceSize > 0) settings.faceSize = desc.faceSize;
        // The sky is computed in the world frame; rotating it would move it away from the sun.
        env.rotationDegrees = 0;
        env.cubemap = std::make_shared<const Cubemap>(bakePreethamSky(sun.direction, sun.irradiance, settings));
    }
    return env;
}

}  // namespace veduta
