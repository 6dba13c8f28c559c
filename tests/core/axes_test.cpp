#include <gtest/gtest.h>

#include "core/axes.h"

namespace veduta {
namespace {

void expectNear(const Vec3f &a, const Vec3f &b) {
    EXPECT_NEAR(a.x, b.x, 1e-6f);
    EXPECT_NEAR(a.y, b.y, 1e-6f);
    EXPECT_NEAR(a.z, b.z, 1e-6f);
}

// T12 of Bilke 2009: TransformGeoZUp maps (1,2,3) to (1,−3,2).
TEST(Axes, TransformGeoZUpMapsSeedExample) {
    EXPECT_EQ(yUpToZUp({1, 2, 3}), Vec3f(1, -3, 2));
    EXPECT_EQ(kYUpToZUp.applyPoint({1, 2, 3}), Vec3f(1, -3, 2));
    EXPECT_EQ(zUpToYUp({1, -3, 2}), Vec3f(1, 2, 3));
    EXPECT_EQ(kZUpToYUp.applyPoint({1, -3, 2}), Vec3f(1, 2, 3));
}

TEST(Axes, UpGoesUp) {
    EXPECT_EQ(yUpToZUp({0, 1, 0}), Vec3f(0, 0, 1));
    EXPECT_EQ(zUpToYUp({0, 0, 1}), Vec3f(0, 1, 0));
}

TEST(Axes, ConversionsRoundTrip) {
    for (Vec3f p : {Vec3f(0.3f, -7, 12.5f), Vec3f(-1, 0, 4), Vec3f(100, 200, -300)}) {
        EXPECT_EQ(zUpToYUp(yUpToZUp(p)), p);
        EXPECT_EQ(yUpToZUp(zUpToYUp(p)), p);
        expectNear((kZUpToYUp * kYUpToZUp).applyPoint(p), p);
    }
    EXPECT_EQ(kYUpToZUp.inverse(), kZUpToYUp);
}

TEST(Axes, FunctionsAndTransformsAgree) {
    Vec3f p(0.25f, -4, 9);
    EXPECT_EQ(kYUpToZUp.applyPoint(p), yUpToZUp(p));
    EXPECT_EQ(kZUpToYUp.applyPoint(p), zUpToYUp(p));
}

TEST(Axes, BothAreRotations) {
    for (const Transform &t : {kYUpToZUp, kZUpToYUp}) {
        EXPECT_FLOAT_EQ(t.determinant(), 1.0f);
        // Orthonormal: the normal transform (inverse transpose) is the matrix itself.
        EXPECT_EQ(t.normalTransform(), t);
        for (Vec3f v : {Vec3f(1, 0, 0), Vec3f(0, 1, 0), Vec3f(0, 0, 1)})
            EXPECT_FLOAT_EQ(length(t.applyVector(v)), 1.0f);
    }
}

}  // namespace
}  // namespace veduta
