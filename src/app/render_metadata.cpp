#include "app/render_metadata.h"

#include <cmath>

#include <fmt/format.h>

#include "app/version.h"
#include "film/adaptive_sampling.h"
#include "scene/scene_hash.h"

namespace veduta {

Matrix44 worldToCamera(const Camera &camera) {
    Vec3f back = normalize(camera.position - camera.lookAt);
    Vec3f right = normalize(cross(camera.up, back));
    Vec3f up = cross(back, right);
    const Vec3f &p = camera.position;
    return {right.x,        up.x,        back.x,        0,  //
            right.y,        up.y,        back.y,        0,  //
            right.z,        up.z,        back.z,        0,  //
            -dot(right, p), -dot(up, p), -dot(back, p), 1};
}

void addRenderMetadata(LayeredImage &image, const SceneDescription &description, const RenderScene &scene,
                       const RenderOptions &options, const RenderStats &stats, uint64_t sceneHash) {
    const Camera &c = scene.camera;
    const RenderSettings &s = scene.settings;
    auto &m = image.metadata;
    m["Software"] = fmt::format("veduta {}", kVersion);
    m["RenderTime"] = blenderRenderTime(stats.seconds);
    m[kRenderSecondsAttribute] = stats.seconds;
    m[kSamplesAttribute] = int(stats.samplesDone);
    m[kSampleOffsetAttribute] = int(options.sampleOffset);
    m[kSeedAttribute] = int(s.seed);
    m[kSceneHashAttribute] = hashText(sceneHash);
    if (s.noiseThreshold > 0) {
        m["veduta.noiseThreshold"] = double(s.noiseThreshold);
        m["veduta.minSamples"] = int(adaptiveMinSamples(s));
    }
    m["veduta.camera"] =
        fmt::format("position {} {} {}, look at {} {} {}, up {} {} {}, vertical fov {}°", c.position.x, c.position.y,
                    c.position.z, c.lookAt.x, c.lookAt.y, c.lookAt.z, c.up.x, c.up.y, c.up.z, c.verticalFovDegrees);
    m["worldToCamera"] = worldToCamera(c);
    if (description.georeference) {
        const Georeference &g = *description.georeference;
        m["veduta.crs"] = fmt::format("EPSG:{}", g.epsg);
        m["veduta.origin"] = fmt::format("{:.3f} {:.3f}", g.originEasting, g.originNorthing);
    } else {
        m["veduta.crs"] = std::string("local (no georeference)");
    }
}

}  // namespace veduta
