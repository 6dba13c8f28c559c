// Dormers and chimneys on a built roof (issue 23): dormers only on the street's slope, on it
// and within it, their roofs meeting the slope; chimneys through the roof beside the ridge;
// settings read and checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "city/roof_fixtures.h"
#include "city/roof_shapes.h"
#include "city/roofs.h"
#include "core/error.h"

namespace veduta {
namespace {

// A 12 × 9 m house, eaves at 10 m, street along its south edge (edge 0), gable roof of 45°
// with the ridge along x.
struct House {
    Footprint footprint;
    Mesh roof;

    House() {
        footprint.points = {{0, 0}, {12, 0}, {12, 9}, {0, 9}};
        footprint.streetEdges = {true, false, false, false};
        RoofOptions options;
        options.type = RoofType::Gable;
        options.pitchDegrees = 45;
        roof = buildRoof({footprint.points, {}, 0}, 10, options).mesh;
    }
};

float roofTop(const Mesh &roof) {
    float top = -1e30f;
    for (const Vec3f &p : roof.positions) top = std::max(top, p.z);
    return top;
}

TEST(RoofFixtures, DormersStandOnTheStreetSlopeOnly) {
    House house;
    RoofFixtureOptions options;
    options.dormers = 3;
    Mesh fixtures = roofFixtures(house.roof, house.footprint, options, 1, 7);
    ASSERT_GT(fixtures.triangleCount(), 0u);
    int windows = 0;
    for (size_t t = 0; t < fixtures.triangleCount(); ++t)
        if (fixtures.triangleMaterials[t] == FixtureWindow) ++windows;
    EXPECT_EQ(windows, 3 * 2);  // a window quad a dormer
    for (const Vec3f &p : fixtures.positions) {
        // On the south (street) slope, which runs from y = 0 at 10 m up to the ridge at y = 4.5.
        EXPECT_LT(p.y, 4.5f + 1e-3f);
        EXPECT_GT(p.y, -0.25f);  // the dormer roof's eave reaches 0.2 m over the front
        EXPECT_GE(p.x, 0.0f);
        EXPECT_LE(p.x, 12.0f);
        // Never above the ridge, never below the slope under it (45°: z = 10 + y) but by the
        // front's own eave.
        EXPECT_LE(p.z, roofTop(house.roof) + 1e-3f);
        if (p.y >= 0) {
            EXPECT_GE(p.z, 10 + p.y - 1e-3f) << p.x << " " << p.y << " " << p.z;
        }
    }
    // A house with no street edge has no dormers.
    house.footprint.streetEdges = {false, false, false, false};
    EXPECT_EQ(roofFixtures(house.roof, house.footprint, options, 1, 7).triangleCount(), 0u);
}

TEST(RoofFixtures, AsManyDormersAsFitOneMetreApart) {
    House house;
    RoofFixtureOptions options;
    options.dormers = 12;
    options.dormerWidth = 3;
    Mesh fixtures = roofFixtures(house.roof, house.footprint, options, 1, 7);
    int windows = 0;
    for (size_t t = 0; t < fixtures.triangleCount(); ++t)
        if (fixtures.triangleMaterials[t] == FixtureWindow) ++windows;
    // 12 m of eaves hold three 3 m dormers 1 m apart.
    EXPECT_EQ(windows, 3 * 2);
}

TEST(RoofFixtures, ChimneysRiseThroughTheRoofBesideTheRidge) {
    House house;
    RoofFixtureOptions options;
    options.chimneys = 2;
    Mesh fixtures = roofFixtures(house.roof, house.footprint, options, 1, 7);
    ASSERT_EQ(fixtures.triangleCount(), 2u * 5 * 2);  // four sides and a top, two triangles each
    float top = roofTop(house.roof);
    float highest = -1e30f, lowest = 1e30f;
    for (const Vec3f &p : fixtures.positions) {
        highest = std::max(highest, p.z), lowest = std::min(lowest, p.z);
        // Beside the ridge (y = 4.5): its near side 0.4 m off it, its far side 0.9 m.
        EXPECT_GE(std::abs(p.y - 4.5f), 0.4f - 1e-3f);
        EXPECT_LE(std::abs(p.y - 4.5f), 0.9f + 1e-3f);
    }
    // 0.9 m over the highest roof under it, 0.4 m from the ridge at 45°: 0.5 m over the ridge.
    EXPECT_NEAR(highest, top + 0.5f, 1e-3f);
    EXPECT_LT(lowest, top - 0.4f);  // it starts inside the roof
}

TEST(RoofFixtures, SettingsAreReadAndChecked) {
    SettingsMap map;
    map["Dormers"] = {"2", 2.0f, {}};
    map["Chimneys"] = {"1", 1.0f, {}};
    map["DormerWidth"] = {"1.8", 1.8f, {}};
    SettingsStack settings({&map});
    RoofFixtureOptions o = roofFixtureOptionsFor(settings);
    EXPECT_EQ(o.dormers, 2);
    EXPECT_EQ(o.chimneys, 1);
    EXPECT_EQ(o.dormerWidth, 1.8f);
    map["Dormers"] = {"2.5", 2.5f, {"rules.xml", 3, 5}};
    EXPECT_THROW(roofFixtureOptionsFor(settings), InputError);
    map["Dormers"] = {"2", 2.0f, {}};
    map["ChimneyHeight"] = {"-1", -1.0f, {"rules.xml", 4, 5}};
    EXPECT_THROW(roofFixtureOptionsFor(settings), InputError);
}

}  // namespace
}  // namespace veduta
