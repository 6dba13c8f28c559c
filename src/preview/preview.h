// The preview: a software rasterizer over the same RenderScene the path tracer reads
// (instances are drawn as instances, never flattened), for quick checks before a long render.
// It uses the scene's camera exactly like the renderer, with the same pixel centres.
#pragma once

#include <cstdint>
#include <vector>

#include "core/rgba_image.h"
#include "scene/render_scene.h"

namespace veduta {

enum class PreviewMode {
    Shaded,  // textured materials lit by the sun (Lambert and Phong, optionally shadowed) and the sky
    Albedo,  // the diffuse albedo, as the path tracer's albedo pass
    Normal,  // shading normal with its normal map, world space, mapped from [-1, 1] to [0, 1]
    Depth,   // distance along the view axis, near = white, far = black
    Id,      // object ids as distinct colours
    Thesis,  // seed 000's per-pixel shader PPSUNS (thesis_shading.h)
};

struct PreviewOptions {
    PreviewMode mode = PreviewMode::Shaded;
    bool wireframe = false;        // draw triangle edges over the image
    bool backfaceCulling = false;  // skip triangles facing away (scenes are two-sided by default)
    bool shadows = false;          // sun shadows from a shadow map (shaded mode)
    int shadowMapSize = 2048;      // texels on a side
    int tileSize = 64;             // pixels; changes speed only
};

// What the preview computed per pixel, top row first.
struct PreviewImage {
    RgbaImage film;                  // the chosen mode's colours, linear (PNG output applies sRGB)
    std::vector<float> depth;        // view-axis distance; +infinity where no geometry
    std::vector<uint32_t> objectId;  // 0 where no geometry
};

PreviewImage renderPreview(const RenderScene &scene, const PreviewOptions &options);
// The same into an image from an earlier call, reusing its memory (for interactive use and
// benchmarks that draw many frames).
void renderPreview(const RenderScene &scene, const PreviewOptions &options, PreviewImage &image);

// The colour the `id` mode gives an object id: well spread, stable, 0 black.
Vec3f objectIdColor(uint32_t id);

}  // namespace veduta
