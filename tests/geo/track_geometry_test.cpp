// A railway's sleepers and rails near the camera (issue 23): only within the reach, where the
// ballast texture draws them, on the ribbon at their heights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geo/geo_test_terrain.h"
#include "geo/ribbons.h"
#include "geo/track_geometry.h"

namespace veduta {
namespace {

const MapPoint kSouthWest{3392030, 5588000};
const LocalFrame kFrame{{3392030, 5588000}};

TEST(TrackGeometry, SleepersAndRailsNearTheCameraOnly) {
    test::DrapedDgm flat(test::flatTerrain(41, 11, 5.0, kSouthWest, 80), kFrame);
    RibbonOptions options;
    options.lift = 0.09;
    // A single track 100 m along x at y = 25; the camera over its start.
    Mesh ribbon = drapeRibbon(
        {{kSouthWest.easting + 20, kSouthWest.northing + 25}, {kSouthWest.easting + 120, kSouthWest.northing + 25}},
        4.5, flat.surface, kFrame, options);
    TrackOptions reach;
    reach.reach = 30;
    Mesh track = trackGeometry(ribbon, 4.5, 1, {20, 25, 82}, reach);
    ASSERT_GT(track.triangleCount(), 0u);
    float ballast = 80 + 0.09f;
    size_t sleeperTriangles = 0;
    float farthest = 0, sleeperTop = -1e30f, railTop = -1e30f;
    for (size_t t = 0; t < track.triangleCount(); ++t) {
        for (int k = 0; k < 3; ++k) {
            Vec3f p = track.positions[track.indices[3 * t + k]];
            farthest = std::max(farthest, p.x - 20);
            if (track.triangleMaterials[t] == TrackSleeper) {
                sleeperTop = std::max(sleeperTop, p.z);
                EXPECT_LE(std::abs(p.y - 25), 1.3f + 1e-4f);
            } else {
                railTop = std::max(railTop, p.z);
                float off = std::abs(p.y - 25);
                EXPECT_NEAR(off, 0.7525f, 0.035f + 1e-4f);
            }
        }
        sleeperTriangles += track.triangleMaterials[t] == TrackSleeper;
    }
    // Sleepers every 0.6 m up to 30 m from the camera (2 m above the track): about 50.
    size_t sleepers = sleeperTriangles / 10;  // a top and four sides, two triangles each
    EXPECT_GE(sleepers, 48u);
    EXPECT_LE(sleepers, 51u);
    EXPECT_LT(farthest, 31.0f);
    EXPECT_NEAR(sleeperTop, ballast + 0.1f, 1e-3f);
    EXPECT_NEAR(railTop, ballast + 0.15f, 1e-3f);
    // Far from the camera: nothing.
    EXPECT_EQ(trackGeometry(ribbon, 4.5, 1, {500, 500, 100}, reach).triangleCount(), 0u);
}

}  // namespace
}  // namespace veduta
