// The camera against analytic expectations: where a point appears for a pinhole, with lens
// shift and orthographically; where a thin lens's rays meet; the focal length and aperture.
#include <cmath>

#include <gtest/gtest.h>

#include "scene/camera.h"

namespace veduta {
namespace {

// Looking north along +y from the origin, z up: right is +x.
Camera northCamera() {
    Camera c;
    c.position = {0, 0, 0};
    c.lookAt = {0, 10, 0};
    c.up = {0, 0, 1};
    c.verticalFovDegrees = 60;
    c.width = 400;
    c.height = 200;
    return c;
}

// Where a ray meets the plane y = depth.
Vec3f pointAlong(const Ray &ray, float depth) {
    return ray.origin + ray.direction * ((depth - ray.origin.y) / ray.direction.y);
}

TEST(Camera, PinholeImagesAPointByTheTangentOfItsAngle) {
    Camera c = northCamera();
    CameraRays rays(c);
    // A point 20 m ahead, 3 m right and 4 m up: x = w/2 + (3/20)/tan(30°)·h/2 (square pixels).
    float scale = 100.0f / std::tan(radians(30.0f));
    float x, y;
    ASSERT_TRUE(rays.project({3, 20, 4}, x, y));
    EXPECT_NEAR(x, 200 + 3.0f / 20 * scale, 1e-3f);
    EXPECT_NEAR(y, 100 - 4.0f / 20 * scale, 1e-3f);
    // And the ray through that raster position passes through the point.
    Vec3f p = pointAlong(rays.generate(x, y), 20);
    EXPECT_NEAR(p.x, 3, 1e-4f);
    EXPECT_NEAR(p.z, 4, 1e-4f);
    EXPECT_FALSE(rays.project({0, -5, 0}, x, y));  // behind
}

// Blender's shift: the frame slides by shift × the longer side (here the width, 400 px),
// the view direction stays, so a point moves the other way on the raster by as many pixels.
TEST(Camera, LensShiftMovesTheFrameByBlendersMeasure) {
    Camera c = northCamera();
    float x0, y0;
    CameraRays(c).project({3, 20, 4}, x0, y0);
    c.shift = {0.1f, 0.25f};
    CameraRays shifted(c);
    float x, y;
    ASSERT_TRUE(shifted.project({3, 20, 4}, x, y));
    EXPECT_NEAR(x, x0 - 0.1f * 400, 1e-3f);
    EXPECT_NEAR(y, y0 + 0.25f * 400, 1e-3f);
    // Verticals stay vertical: a vertical edge keeps one x at every height.
    float xBottom, yBottom, xTop, yTop;
    shifted.project({5, 30, -2}, xBottom, yBottom);
    shifted.project({5, 30, 12}, xTop, yTop);
    EXPECT_NEAR(xBottom, xTop, 1e-3f);
    // The ray through the centre of the shifted frame is not the view axis.
    Ray centre = shifted.generate(200, 100);
    EXPECT_GT(centre.direction.z, 0.2f);
}

// Orthographic: ortho_scale metres across the longer side, parallel rays along the view axis.
TEST(Camera, OrthographicMapsMetresToPixelsEverywhereAlike) {
    Camera c = northCamera();
    c.projection = Projection::Orthographic;
    c.orthoScale = 40;  // 400 px wide: 10 px a metre
    CameraRays rays(c);
    for (float depth : {5.0f, 50.0f, 500.0f}) {
        float x, y;
        ASSERT_TRUE(rays.project({3, depth, 4}, x, y));
        EXPECT_NEAR(x, 200 + 30, 1e-3f);
        EXPECT_NEAR(y, 100 - 40, 1e-3f);
    }
    Ray r = rays.generate(230, 60);
    EXPECT_NEAR(r.direction.y, 1, 1e-6f);
    EXPECT_NEAR(r.origin.x, 3, 1e-4f);
    EXPECT_NEAR(r.origin.z, 4, 1e-4f);
    c.shift = {0.5f, 0};  // half of 40 m
    float x, y;
    CameraRays(c).project({3, 7, 4}, x, y);
    EXPECT_NEAR(x, 230 - 200, 1e-3f);
}

// A box's diagonal in pixels agrees with where its ends project when it stands face on at the
// image's centre; beside the view, at the same distance, it counts as large.
TEST(Camera, PixelsSpannedAreWhatAFaceOnBoxCoversOnTheRaster) {
    Camera c = northCamera();
    CameraRays rays(c);
    float x0, y0, x1, y1;
    ASSERT_TRUE(rays.project({0, 40, -3}, x0, y0));
    ASSERT_TRUE(rays.project({0, 40, 3}, x1, y1));
    EXPECT_NEAR(c.pixelsSpanned({0, 40, -3}, {0, 40, 3}), y0 - y1, 1e-3f);
    EXPECT_NEAR(c.pixelsSpanned({40, 0, -3}, {40, 0, 3}), y0 - y1, 1e-3f);
    EXPECT_NEAR(c.pixelsSpanned({0, 80, -3}, {0, 80, 3}), (y0 - y1) / 2, 1e-3f);
    c.projection = Projection::Orthographic;
    c.orthoScale = 40;  // 10 px a metre, at any distance
    EXPECT_NEAR(c.pixelsSpanned({0, 500, 0}, {3, 500, 4}), 50, 1e-3f);
}

// Blender's camera: lens = sensor / 2 / tan(fov / 2) along the longer side, aperture = lens / N.
TEST(Camera, FocalLengthAndApertureFollowTheSensor) {
    Camera c = northCamera();
    float horizontalHalf = std::atan(std::tan(radians(30.0f)) * 2);  // 400 × 200 px
    EXPECT_NEAR(c.focalLength(), 0.018f / std::tan(horizontalHalf), 1e-7f);
    c.fNumber = 2.8f;
    EXPECT_NEAR(c.apertureRadius(), 0.5f * c.focalLength() / 2.8f, 1e-8f);
    EXPECT_NEAR(c.focusPlaneDistance(), 10, 1e-5f);  // look_at's distance
}

// Every ray of a raster position meets at its point on the plane in focus; a point off that
// plane is seen along a disc of the diameter the thin-lens equation gives.
TEST(Camera, ThinLensRaysMeetOnThePlaneInFocusAndSpreadElsewhere) {
    Camera c = northCamera();
    c.fNumber = 1.4f;
    c.focusDistance = 12;
    CameraRays rays(c);
    const float apertureDiameter = 2 * c.apertureRadius();
    Vec3f pinhole = pointAlong(rays.generate(250, 80), 12);
    for (Vec2f lens : {Vec2f{1, 0}, Vec2f{0, 1}, Vec2f{-0.6f, 0.8f}, Vec2f{0.3f, -0.2f}}) {
        Ray r = rays.generate(250, 80, lens);
        EXPECT_NEAR(length(r.origin), std::hypot(lens.x, lens.y) * c.apertureRadius(), 1e-6f);
        Vec3f p = pointAlong(r, 12);
        EXPECT_NEAR(length(p - pinhole), 0, 1e-4f);
    }
    // At 48 m, rays from opposite rims of the lens through one raster position are
    // A·|d − s|/s apart (similar triangles through the focus point).
    Vec3f a = pointAlong(rays.generate(250, 80, {1, 0}), 48), b = pointAlong(rays.generate(250, 80, {-1, 0}), 48);
    EXPECT_NEAR(length(a - b), apertureDiameter * (48 - 12) / 12, 1e-5f);
}

}  // namespace
}  // namespace veduta
