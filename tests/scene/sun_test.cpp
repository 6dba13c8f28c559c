#include <gtest/gtest.h>

#include "scene/sun.h"

namespace veduta {
namespace {

// A direction `angle` degrees away from `axis`, turned about a perpendicular.
Vec3f tilted(const Vec3f &axis, float angle) {
    Frame f = Frame::fromNormal(axis);
    return normalize(f.toWorld({std::sin(radians(angle)), 0, std::cos(radians(angle))}));
}

TEST(Sun, DiscContainsWhatIsInsideItsRadiusEvenForTinyDiscs) {
    for (float diameter : {0.01f, 0.53f, 5.0f}) {
        Sun sun;
        sun.direction = normalize(Vec3f{0.3f, -0.5f, 0.8f});
        sun.angularDiameterDegrees = diameter;
        EXPECT_TRUE(sun.discContains(sun.direction)) << diameter;
        EXPECT_TRUE(sun.discContains(tilted(sun.direction, 0.45f * diameter))) << diameter;
        EXPECT_FALSE(sun.discContains(tilted(sun.direction, 0.55f * diameter))) << diameter;
        EXPECT_FALSE(sun.discContains(-sun.direction)) << diameter;
    }
}

TEST(Sun, OneMinusCosRadiusIsExactForSmallDiscs) {
    Sun sun;
    sun.angularDiameterDegrees = 0.02f;
    double radius = 0.01 * M_PI / 180;
    EXPECT_NEAR(sun.oneMinusCosRadius(), radius * radius / 2, 1e-6 * radius * radius);
}

TEST(Sun, AzimuthIsClockwiseFromNorth) {
    Vec3f east = Sun::directionFromAzimuthElevation(90, 0);
    EXPECT_NEAR(east.x, 1, 1e-6);
    Vec3f south = Sun::directionFromAzimuthElevation(180, 0);
    EXPECT_NEAR(south.y, -1, 1e-6);
    Vec3f zenith = Sun::directionFromAzimuthElevation(0, 90);
    EXPECT_NEAR(zenith.z, 1, 1e-6);
}

}  // namespace
}  // namespace veduta
