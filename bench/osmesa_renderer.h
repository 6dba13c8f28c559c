// A reference for the preview: the same RenderScene drawn by Mesa's llvmpipe through OSMesa,
// off-screen, with the preview's camera and its Shaded model (Lambert sun without shadows plus
// the sky's irradiance, surfaces two-sided). Prototypes are uploaded once and drawn instanced,
// as the preview draws them, so a benchmark compares two rasterizers doing the same work.
#pragma once

#include <memory>
#include <string>

#include "core/rgba_image.h"
#include "scene/render_scene.h"

namespace veduta {

class OsMesaRenderer {
  public:
    // Creates a GL 3.3 core context at the camera's resolution, uploads the scene and draws
    // one frame, so that llvmpipe's shader compilation is not part of the first timed frame.
    // llvmpipe reads LP_NUM_THREADS when the process creates its first context: set it before.
    // Throws std::runtime_error when OSMesa or GL fail.
    explicit OsMesaRenderer(const RenderScene &scene);
    ~OsMesaRenderer();
    OsMesaRenderer(const OsMesaRenderer &) = delete;
    OsMesaRenderer &operator=(const OsMesaRenderer &) = delete;

    // Clears, draws every mesh and instance, and waits with glFinish until the pixels are in
    // the colour buffer in memory: one frame, as a benchmark should time it.
    void drawFrame();

    // The last frame: linear RGBA float, top row first, like the preview's RgbaImage.
    RgbaImage image() const;

    // GL_RENDERER and GL_VERSION, to show which driver drew.
    std::string description() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace veduta
