#include "scene/camera.h"

#include <cmath>

namespace veduta {

Ray Camera::generateRay(float x, float y) const {
    Vec3f forward = normalize(lookAt - position);
    Vec3f right = normalize(cross(forward, up));
    Vec3f trueUp = cross(right, forward);
    float tanHalf = std::tan(radians(verticalFovDegrees) * 0.5f);
    float aspect = float(width) / float(height);
    float sx = (2.0f * x / float(width) - 1.0f) * tanHalf * aspect;
    float sy = (1.0f - 2.0f * y / float(height)) * tanHalf;
    return {position, normalize(forward + right * sx + trueUp * sy)};
}

}  // namespace veduta
