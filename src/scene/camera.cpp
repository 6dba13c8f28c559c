#include "scene/camera.h"

#include <cmath>

namespace veduta {

CameraRays::CameraRays(const Camera &camera) : origin_(camera.position) {
    Vec3f forward = normalize(camera.lookAt - camera.position);
    Vec3f right = normalize(cross(forward, camera.up));
    Vec3f up = cross(right, forward);
    float halfHeight = std::tan(radians(camera.verticalFovDegrees) * 0.5f);
    float halfWidth = halfHeight * float(camera.width) / float(camera.height);
    topLeft_ = forward - right * halfWidth + up * halfHeight;
    pixelRight_ = right * (2 * halfWidth / float(camera.width));
    pixelDown_ = up * (-2 * halfHeight / float(camera.height));
}

}  // namespace veduta
