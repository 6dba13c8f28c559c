// The camera matrices of the render's EXR: worldToNDC puts a point where the camera's own
// projection puts it on the raster, for perspective and orthographic cameras with lens shift.
#include <gtest/gtest.h>

#include "app/render_metadata.h"

namespace veduta {
namespace {

// p · M for a row vector (x, y, z, 1), divided by w.
Vec3f transformed(const Matrix44 &m, const Vec3f &p) {
    float out[4];
    for (int c = 0; c < 4; ++c) {
        out[c] = p.x * m[size_t(c)] + p.y * m[size_t(4 + c)] + p.z * m[size_t(8 + c)] + m[size_t(12 + c)];
    }
    return {out[0] / out[3], out[1] / out[3], out[2] / out[3]};
}

TEST(RenderMetadata, WorldToNdcAgreesWithTheCamerasProjection) {
    for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        Camera camera;
        camera.projection = projection;
        camera.position = {3, -20, 5};
        camera.lookAt = {-1, 4, 2};
        camera.width = 320;
        camera.height = 180;
        camera.shift = {0.1f, -0.05f};
        CameraRays rays(camera);
        Matrix44 m = worldToNdc(camera);
        int checked = 0;
        for (Vec3f point : {Vec3f{0, 0, 0}, Vec3f{-4, 6, 3}, Vec3f{2, 10, -1}, Vec3f{-1, 4, 2}}) {
            float x, y;
            ASSERT_TRUE(rays.project(point, x, y));
            Vec3f ndc = transformed(m, point);
            EXPECT_NEAR(ndc.x * float(camera.width), x, 1e-3f) << int(projection);
            EXPECT_NEAR(ndc.y * float(camera.height), y, 1e-3f) << int(projection);
            ++checked;
        }
        EXPECT_EQ(checked, 4);
    }
}

}  // namespace
}  // namespace veduta
