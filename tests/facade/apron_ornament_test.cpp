// The relief of a window's apron (apron_ornament.h): an ornament grown into the left half of the
// panel, mirrored, inside a moulded rim.
#include "facade/apron_ornament.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "facade/building_description.h"
#include "facade/facade_building.h"
#include "facade/masonry_texture.h"

namespace veduta {
namespace {

TEST(ApronRelief, IsMirrorSymmetricWithARimAndAnOrnamentInside) {
    Image relief = apronRelief(1.2, 0.5);
    ASSERT_EQ(relief.width, 120);
    ASSERT_EQ(relief.height, 50);
    ASSERT_EQ(relief.channels, 1);
    size_t raised = 0, field = 0;
    float highest = 0;
    for (int row = 0; row < relief.height; ++row)
        for (int x = 0; x < relief.width; ++x) {
            float h = *relief.at(x, row);
            EXPECT_EQ(h, *relief.at(relief.width - 1 - x, row)) << x << " " << row;
            highest = std::max(highest, h);
            bool edge = x == 0 || row == 0 || x == relief.width - 1 || row == relief.height - 1;
            if (edge) {
                EXPECT_FLOAT_EQ(h, float(kApronRimHeight)) << "the rim's flat top at the edge";
            }
            bool inside = x >= 4 && x < relief.width - 4 && row >= 4 && row < relief.height - 4;
            if (inside) {
                ++field;
                raised += h > 0;
            }
        }
    // The ornament covers a good part of the field inside the rim, and stands a few millimetres.
    std::printf("apron 1.2 × 0.5 m: %zu of %zu field cells raised, highest %.4f m\n", raised, field, highest);
    EXPECT_GT(double(raised), 0.2 * double(field));
    EXPECT_LT(highest, 0.02f);
    // The same size gives the same relief: growth draws nothing at random.
    EXPECT_EQ(apronRelief(1.2, 0.5).pixels, relief.pixels);
}

TEST(ApronRelief, APanelTooSmallForItsRimIsRefused) {
    EXPECT_THROW(apronRelief(0.1, 0.5), std::invalid_argument);
    EXPECT_THROW(apronRelief(1.0, 0.11), std::invalid_argument);
    EXPECT_THROW(apronRelief(11, 0.5), std::invalid_argument);
    Image smallest = apronRelief(3 * kApronRimWidth, 3 * kApronRimWidth);
    EXPECT_EQ(smallest.width, 12);
}

// A box of one storey whose every wall has windows with aprons: each placed window has its panel,
// 3 cm proud of the wall, whose face is a masonry wall of the relief alone; baked, that face's
// normals show the ornament where a plain wall's are flat.
TEST(ApronRelief, EveryWindowOfItsStyleGetsAPanelBakedAsRelief) {
    BuildingStructure structure = parseBuildingStructure(
        "Module { \"A\"; 0, 0; 10, 0; 10, 8; 0, 8; }\nStoreys { \"A\"; 3.5; }\nRoof { \"A\"; flat, 1, 0.3; }",
        "t.structure");
    BuildingStyle style = parseBuildingStyle(
        "Style { \"s\"; window, 0, 1.2, 1.6, 1.0, 1, 1; apron, 0, 0.6, 0.03; }\nBind { building, \"s\"; }", "t.style",
        [](const std::string &, const FileLoc &) { return std::string(); });
    FacadeBuilding building = buildFacadeBuilding(
        structure, style, [](const std::string &, const FileLoc &) { return MaterialId(0); }, 1, 1);
    ASSERT_GT(building.openings, 0u);
    size_t aprons = 0;
    for (const MasonryWall &wall : building.masonry) {
        if (!wall.masonry.relief) continue;
        ++aprons;
        EXPECT_TRUE(wall.masonry.stones.empty());
        ASSERT_EQ(wall.triangles.size(), 2u);
        // The face: 0.6 m high right under the window's hole, as wide as the hole to the centimetre.
        Vec2d low = wall.face.outline[0], high = wall.face.outline[2];
        EXPECT_NEAR(high.y - low.y, 0.6, 1e-9);
        EXPECT_LE(high.y, 1.0 + 1e-9);
        EXPECT_GT(low.y, 0.05);
        // Its triangles stand 3 cm out of the footprint, facing out.
        const Mesh &mesh = building.mesh;
        for (uint32_t t : wall.triangles)
            for (int k = 0; k < 3; ++k) {
                uint32_t v = mesh.indices[3 * t + uint32_t(k)];
                Vec3f p = mesh.positions[v], n = mesh.normals[v];
                double outside = std::max({-double(p.y), double(p.x) - 10, double(p.y) - 8, -double(p.x)});
                EXPECT_NEAR(outside, 0.03, 1e-5) << p.x << " " << p.y;
                EXPECT_NEAR(std::hypot(n.x, n.y), 1.0, 1e-6);
            }
        MasonryTextures baked = bakeMasonry(wall.masonry, wall.face, 0.005);
        size_t tilted = 0;
        for (int row = 0; row < baked.normal.height; ++row)
            for (int x = 0; x < baked.normal.width; ++x) tilted += baked.normal.at(x, row)[2] < 0.5f + 0.5f * 0.99f;
        EXPECT_GT(tilted, size_t(baked.normal.width * baked.normal.height / 10)) << "the ornament shows in the normals";
    }
    EXPECT_EQ(aprons, building.openings);
}

}  // namespace
}  // namespace veduta
