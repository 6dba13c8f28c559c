// The camera: where the viewer stands, how the image is framed (perspective or orthographic,
// lens shift) and how much lies in focus (a thin lens), and how raster positions map to rays.
#pragma once

#include "core/vecmath.h"

namespace veduta {

struct Ray {
    Vec3f origin;
    Vec3f direction;  // unit length
};

enum class Projection { Perspective, Orthographic };

// The camera's axes: forward towards look_at, right, and up as the image's up.
struct CameraAxes {
    Vec3f forward, right, up;
};

struct Camera {
    Vec3f position{0, -10, 2};
    Vec3f lookAt{0, 0, 2};
    Vec3f up{0, 0, 1};
    Projection projection = Projection::Perspective;
    float verticalFovDegrees = 45;  // perspective
    float orthoScale = 10;          // orthographic: metres the longer image side spans (Blender's)
    // Lens shift, in image widths of the longer side, as Blender's shift_x / shift_y: the frame
    // slides right and up in the image plane while the view direction stays, so verticals stay
    // vertical when the camera looks level and the facade's top is shifted into the frame.
    Vec2f shift;
    // Depth of field (thin lens): 0 is a pinhole. The aperture's diameter is the focal length
    // over fNumber, the focal length following from the field of view on a sensor of
    // sensorWidth millimetres along the longer side (Blender's default 36 mm, sensor fit auto).
    float fNumber = 0;
    float focusDistance = 0;  // metres along the view axis; 0 = as far as look_at
    float sensorWidth = 36;   // mm
    int width = 640;
    int height = 360;

    // What keeps position, look_at and up from framing a view (the same point, or up along
    // the view), or nullptr: checked where a camera is read and where it is placed from map
    // coordinates.
    const char *framingProblem() const;
    CameraAxes axes() const;  // for a camera without a framing problem
    bool hasDepthOfField() const { return fNumber > 0; }
    // The focal length in metres and the aperture's radius in metres, for a perspective camera.
    float focalLength() const;
    float apertureRadius() const { return hasDepthOfField() ? 0.5f * focalLength() / fNumber : 0.0f; }
    // Distance from the camera to the plane in focus, along the view axis.
    float focusPlaneDistance() const;
    // Half the frame's extent, right and up, before lens shift: on the plane one metre ahead
    // for a perspective camera, in metres for an orthographic one.
    Vec2f halfExtent() const;
    // The pixels of the image's height that the diagonal of the box from `low` to `high` spans,
    // seen face on from the distance of the box's centre: the measure levels of detail are chosen
    // by. Nothing is culled (a building beside or behind the view still casts its shadow and shows
    // in reflections), so it is as large as the box would appear at the image's centre.
    float pixelsSpanned(Vec3f low, Vec3f high) const;
};

// Rays of a camera, with its frame worked out once rather than per sample.
class CameraRays {
  public:
    explicit CameraRays(const Camera &camera);

    // Ray through raster position (x, y): (0, 0) is the top-left corner of the image,
    // (width, height) the bottom-right one. `lens` is a point of the unit disc (the lens's
    // centre is (0, 0)); a pinhole ignores it.
    Ray generate(float x, float y, Vec2f lens = {}) const;

    // Where a point of the world appears on the raster, for a pinhole or the lens's centre;
    // false behind the camera.
    bool project(const Vec3f &point, float &x, float &y) const;

    // The angle a pixel spans at the image centre, for texture footprints (ray cones). An
    // orthographic camera's pixels have a width instead: taken as the angle it spans from the
    // camera at the distance in focus, so footprints are right there.
    float pixelSpread() const;

  private:
    Projection projection_;
    Vec3f origin_;
    CameraAxes axes_;
    // Perspective: the frame on the plane one metre ahead; orthographic: on the camera's plane.
    Vec3f topLeft_, pixelRight_, pixelDown_;
    float pixelWidth_;  // of a pixel on that plane, in its units
    float lensRadius_, focusDistance_;
};

}  // namespace veduta
