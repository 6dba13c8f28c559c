#include "app/render_metadata.h"

#include <algorithm>
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

namespace {

Matrix44 product(const Matrix44 &a, const Matrix44 &b) {
    Matrix44 m{};
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column) {
            for (int k = 0; k < 4; ++k)
                m[size_t(4 * row + column)] += a[size_t(4 * row + k)] * b[size_t(4 * k + column)];
        }
    }
    return m;
}

}  // namespace

Matrix44 worldToNdc(const Camera &camera) {
    Vec2f half = camera.halfExtent();
    float longer = 2 * std::max(half.x, half.y);
    // The frame's corner left and above its centre, lens shift included, in camera units (on the
    // plane one metre ahead for a perspective camera, metres for an orthographic one).
    float left = half.x - camera.shift.x * longer, top = half.y + camera.shift.y * longer;
    float sx = 1 / (2 * half.x), sy = 1 / (2 * half.y);
    // Camera space looks down −z: a perspective camera divides by the distance −z, an
    // orthographic one by 1.
    Matrix44 cameraToNdc = camera.projection == Projection::Perspective
        ? Matrix44{sx, 0, 0, 0, 0, -sy, 0, 0, -left * sx, -top * sy, 0, -1, 0, 0, 1, 0}
        : Matrix44{sx, 0, 0, 0, 0, -sy, 0, 0, 0, 0, 1, 0, left * sx, top * sy, 0, 1};
    return product(worldToCamera(camera), cameraToNdc);
}

void addRenderMetadata(LayeredImage &image, const std::string &sceneFile, const SceneDescription &description,
                       const RenderScene &scene, const RenderOptions &options, const RenderStats &stats,
                       uint64_t sceneHash) {
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
    m["worldToNDC"] = worldToNdc(c);
    m["veduta.scene"] = sceneFile.empty() ? std::string("(built-in default scene)") : sceneFile;
    if (description.georeference) {
        const Georeference &g = *description.georeference;
        m["veduta.crs"] = fmt::format("EPSG:{}", g.epsg);
        m["veduta.origin"] = fmt::format("{:.3f} {:.3f}", g.originEasting, g.originNorthing);
    } else {
        m["veduta.crs"] = std::string("local (no georeference)");
    }
}

}  // namespace veduta
