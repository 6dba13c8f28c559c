// The futuristic city's buildings (digest-002 §4, §6, §10.2): closed prisms with whole-number
// texture repeats on their walls.
#include <gtest/gtest.h>

#include <algorithm>

#include "city/footprint.h"
#include "city/prism_building.h"
#include "scene/solid_checks.h"

namespace veduta {
namespace {

TEST(PrismBuilding, WallsRepeatTheirTextureAWholeNumberOfTimes) {
    EXPECT_EQ(uvRepeats(10.4f, 3), 3);  // the thesis's pair
    EXPECT_EQ(uvRepeats(1, 3), 1);      // at least once
    EXPECT_EQ(uvRepeats(4.4f, 3), 1);
    EXPECT_EQ(uvRepeats(4.6f, 3), 2);
    EXPECT_EQ(uvRepeats(0.01f, 3), 1);
}

const std::vector<Vec2f> kL{{0, 0}, {10.4f, 0}, {10.4f, 4}, {4, 4}, {4, 9}, {0, 9}};

TEST(PrismBuilding, IsAClosedSolidOfItsHeight) {
    Mesh prism = prismBuilding(kL, 30, 12.5f, {3, 3.5f});
    EXPECT_TRUE(isWatertight(prism));
    EXPECT_NEAR(enclosedVolume(prism), signedArea(kL) * 12.5, 1e-2);
    for (const Vec3f &p : prism.positions) {
        EXPECT_GE(p.z, 30);
        EXPECT_LE(p.z, 42.5f);
    }
    // The roof and floor are the footprint's n − 2 triangles each; every wall two.
    auto count = [&](PrismSurface s) {
        return std::count(prism.triangleMaterials.begin(), prism.triangleMaterials.end(), s);
    };
    EXPECT_EQ(count(PrismRoof), 4);
    EXPECT_EQ(count(PrismFloor), 4);
    EXPECT_EQ(count(PrismWall), 12);
}

TEST(PrismBuilding, EachWallShowsWholeTiles) {
    Vec2f tile{3, 3.5f};
    Mesh prism = prismBuilding(kL, 0, 12.5f, tile);
    // The first wall, 10.4 m long and 12.5 m high: 3 tiles across, 4 up (12.5 / 3.5 = 3.57).
    float u = 0, v = 0;
    for (int i = 0; i < 4; ++i) u = std::max(u, prism.uvs[i].x), v = std::max(v, prism.uvs[i].y);
    EXPECT_FLOAT_EQ(u / tile.x, 3);
    EXPECT_FLOAT_EQ(v / tile.y, 4);
    // The third, 6.4 m: twice.
    u = 0;
    for (int i = 8; i < 12; ++i) u = std::max(u, prism.uvs[i].x);
    EXPECT_FLOAT_EQ(u / tile.x, 2);
}

TEST(PrismBuilding, FacesOutAboveAndBelow) {
    Mesh prism = prismBuilding(kL, 5, 8, {3, 3});
    for (size_t t = 0; t < prism.triangleCount(); ++t) {
        const Vec3f &a = prism.positions[prism.indices[3 * t]], &b = prism.positions[prism.indices[3 * t + 1]],
                    &c = prism.positions[prism.indices[3 * t + 2]];
        Vec3f n = cross(b - a, c - a);
        if (prism.triangleMaterials[t] == PrismRoof) {
            EXPECT_GT(n.z, 0) << t;
        } else if (prism.triangleMaterials[t] == PrismFloor) {
            EXPECT_LT(n.z, 0) << t;
        }
        // The stored normals agree with the winding.
        EXPECT_GT(dot(n, prism.normals[prism.indices[3 * t]]), 0) << t;
    }
}

}  // namespace
}  // namespace veduta
