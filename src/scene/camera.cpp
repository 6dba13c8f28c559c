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

float Camera::pixelsSpanned(Vec3f low, Vec3f high) const {
    float diagonal = length(high - low);
    float metresPerPixel = 2 * halfExtent().y / float(height);  // on the plane one metre ahead, or on any
    if (projection == Projection::Orthographic) return diagonal / metresPerPixel;
    float distance = length((low + high) * 0.5f - position);
    return diagonal / (std::max(distance, 1e-3f) * metresPerPixel);
}

const char *Camera::framingProblem() const {
    if (length(lookAt - position) == 0) return "camera position and look_at are the same point";
    if (length(cross(lookAt - position, up)) == 0) return "camera up is parallel to the view direction";
    return nullptr;
}

CameraAxes Camera::axes() const {
    CameraAxes a;
    a.forward = normalize(lookAt - position);
    a.right = normalize(cross(a.forward, up));
    a.up = cross(a.right, a.forward);
    return a;
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
    axes_(camera.axes()),
    lensRadius_(camera.projection == Projection::Perspective ? camera.apertureRadius() : 0.0f),
    focusDistance_(camera.focusPlaneDistance()) {
    Vec2f half = camera.halfExtent();
    float longer = 2 * std::max(half.x, half.y);
    // Blender's shift moves the frame by that many lengths of the longer side.
    Vec3f centre = axes_.right * (camera.shift.x * longer) + axes_.up * (camera.shift.y * longer);
    if (projection_ == Projection::Perspective) centre += axes_.forward;
    topLeft_ = centre - axes_.right * half.x + axes_.up * half.y;
    pixelRight_ = axes_.right * (2 * half.x / float(camera.width));
    pixelDown_ = axes_.up * (-2 * half.y / float(camera.height));
    pixelWidth_ = 2 * half.x / float(camera.width);
}

Ray CameraRays::generate(float x, float y, Vec2f lens) const {
    Vec3f onFrame = topLeft_ + pixelRight_ * x + pixelDown_ * y;
    if (projection_ == Projection::Orthographic) return {origin_ + onFrame, axes_.forward};
    if (lensRadius_ == 0) return {origin_, normalize(onFrame)};
    // onFrame is one metre ahead along the view axis, so this point lies on the plane in focus:
    // every ray through the lens for this raster position meets there.
    Vec3f focus = onFrame * focusDistance_;
    Vec3f lensPoint = (axes_.right * lens.x + axes_.up * lens.y) * lensRadius_;
    return {origin_ + lensPoint, normalize(focus - lensPoint)};
}

float CameraRays::pixelSpread() const {
    return projection_ == Projection::Orthographic ? pixelWidth_ / focusDistance_ : pixelWidth_;
}

bool CameraRays::project(const Vec3f &point, float &x, float &y) const {
    Vec3f d = point - origin_;
    float depth = dot(d, axes_.forward);
    Vec3f onFrame = d;
    if (projection_ == Projection::Perspective) {
        if (depth <= 0) return false;
        onFrame = d / depth;
    } else {
        onFrame = d - axes_.forward * depth;
    }
    Vec3f fromCorner = onFrame - topLeft_;
    x = dot(fromCorner, axes_.right) / pixelWidth_;
    y = -dot(fromCorner, axes_.up) / pixelWidth_;  // square pixels
    return projection_ == Projection::Perspective || depth >= 0;
}

}  // namespace veduta
