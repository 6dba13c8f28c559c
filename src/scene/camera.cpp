#include "scene/camera.h"

#include <algorithm>
#include <cmath>

namespace veduta {

Vec2f Camera::halfExtent() const {
    float aspect = float(width) / float(height);
    if (projection == Projection::Orthographic) {
        float longer = 0.5f * orthoScale;
        return aspect >= 1 ? Vec2f{longer, longer / aspect} : Vec2f{longer * aspect, longer};
    }
    float halfHeight = std::tan(radians(verticalFovDegrees) * 0.5f);
    return {halfHeight * float(width) / float(height), halfHeight};
}

float Camera::focalLength() const {
    Vec2f half = halfExtent();
    return 0.5f * sensorWidth * 1e-3f / std::max(half.x, half.y);
}

float Camera::focusPlaneDistance() const {
    if (focusDistance > 0) return focusDistance;
    return dot(lookAt - position, normalize(lookAt - position));
}

CameraRays::CameraRays(const Camera &camera) :
    projection_(camera.projection),
    origin_(camera.position),
    lensRadius_(camera.projection == Projection::Perspective ? camera.apertureRadius() : 0.0f),
    focusDistance_(camera.focusPlaneDistance()) {
    forward_ = normalize(camera.lookAt - camera.position);
    right_ = normalize(cross(forward_, camera.up));
    up_ = cross(right_, forward_);
    Vec2f half = camera.halfExtent();
    float longer = 2 * std::max(half.x, half.y);
    // Blender's shift moves the frame by that many lengths of the longer side.
    Vec3f centre = right_ * (camera.shift.x * longer) + up_ * (camera.shift.y * longer);
    if (projection_ == Projection::Perspective) centre += forward_;
    topLeft_ = centre - right_ * half.x + up_ * half.y;
    pixelRight_ = right_ * (2 * half.x / float(camera.width));
    pixelDown_ = up_ * (-2 * half.y / float(camera.height));
    pixelWidth_ = 2 * half.x / float(camera.width);
}

Ray CameraRays::generate(float x, float y, Vec2f lens) const {
    Vec3f onFrame = topLeft_ + pixelRight_ * x + pixelDown_ * y;
    if (projection_ == Projection::Orthographic) return {origin_ + onFrame, forward_};
    if (lensRadius_ == 0) return {origin_, normalize(onFrame)};
    // onFrame is one metre ahead along the view axis, so this point lies on the plane in focus:
    // every ray through the lens for this raster position meets there.
    Vec3f focus = onFrame * focusDistance_;
    Vec3f lensPoint = (right_ * lens.x + up_ * lens.y) * lensRadius_;
    return {origin_ + lensPoint, normalize(focus - lensPoint)};
}

float CameraRays::pixelSpread() const {
    return projection_ == Projection::Orthographic ? pixelWidth_ / focusDistance_ : pixelWidth_;
}

bool CameraRays::project(const Vec3f &point, float &x, float &y) const {
    Vec3f d = point - origin_;
    float depth = dot(d, forward_);
    Vec3f onFrame = d;
    if (projection_ == Projection::Perspective) {
        if (depth <= 0) return false;
        onFrame = d / depth;
    } else {
        onFrame = d - forward_ * depth;
    }
    Vec3f fromCorner = onFrame - topLeft_;
    x = dot(fromCorner, right_) / pixelWidth_;
    y = -dot(fromCorner, up_) / pixelWidth_;  // square pixels
    return projection_ == Projection::Perspective || depth >= 0;
}

}  // namespace veduta
