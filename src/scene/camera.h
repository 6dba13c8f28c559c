// The pinhole camera: where the viewer stands and how raster positions map to rays.
#pragma once

#include "core/vecmath.h"

namespace veduta {

struct Ray {
    Vec3f origin;
    Vec3f direction;  // unit length
};

struct Camera {
    Vec3f position{0, -10, 2};
    Vec3f lookAt{0, 0, 2};
    Vec3f up{0, 0, 1};
    float verticalFovDegrees = 45;
    int width = 640;
    int height = 360;
};

// Rays of a camera, with its frame worked out once rather than per sample.
class CameraRays {
  public:
    explicit CameraRays(const Camera &camera);

    // Ray through raster position (x, y): (0, 0) is the top-left corner of the image,
    // (width, height) the bottom-right one.
    Ray generate(float x, float y) const { return {origin_, normalize(topLeft_ + pixelRight_ * x + pixelDown_ * y)}; }

  private:
    Vec3f origin_, topLeft_, pixelRight_, pixelDown_;
};

}  // namespace veduta
