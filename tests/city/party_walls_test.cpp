// Party walls (issue 23): edges built against a neighbour's are found, and become plain walls
// in the material party_wall instead of facades.
#include <gtest/gtest.h>

#include <vector>

#include "assembly/build_scene.h"
#include "city/party_walls.h"
#include "description/scene_description.h"
#include "test_paths.h"

namespace veduta {
namespace {

Footprint box(float x0, float y0, float x1, float y1) {
    Footprint f;
    f.points = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    f.streetEdges = {true, false, false, false};
    return f;
}

TEST(PartyWalls, EdgesBackToBackAreParty) {
    // A row of three houses, the middle one set back by 5 cm (still wall to wall), and a
    // detached one 3 m further on.
    Footprint a = box(0, 0, 10, 12), b = box(10, 0.05f, 18, 12), c = box(18, 0, 30, 9), d = box(33, 0, 40, 10);
    std::vector<const Footprint *> row{&a, &b, &c, &d};
    std::vector<std::vector<bool>> party = partyWalls(row);
    EXPECT_EQ(party[0], (std::vector<bool>{false, true, false, false}));
    EXPECT_EQ(party[1], (std::vector<bool>{false, true, false, true}));
    // c's west edge (18, 9) → (18, 0) meets b's east edge over 9 of its 9 m.
    EXPECT_EQ(party[2], (std::vector<bool>{false, false, false, true}));
    EXPECT_EQ(party[3], (std::vector<bool>{false, false, false, false}));
    // b's east edge meets c's over 9 of its 12 m: party (at least half). An edge touching
    // another over less than half its length is not.
    Footprint e = box(40, 0, 52, 10), f = box(52, 8, 60, 20);
    std::vector<const Footprint *> corner{&e, &f};
    EXPECT_EQ(partyWalls(corner)[0], (std::vector<bool>{false, false, false, false}));
}

TEST(PartyWalls, AreBuiltPlainInTheirMaterial) {
    // Two houses wall to wall, the second lower: the first's east wall shows above it.
    std::string xml = "<scene version=\"1\">\n<buildings rules=\"" +
        test::sourceFile("rules/gruenderzeit/FacadeStructure.xml") +
        "\">\n<building footprint=\"0 0 10 0 10 12 0 12\" street=\"0\"><BuildingSettings>"
        "<BuildingHeight>15</BuildingHeight></BuildingSettings></building>\n"
        "<building footprint=\"10 0 20 0 20 12 10 12\" street=\"0\"><BuildingSettings>"
        "<BuildingHeight>9</BuildingHeight></BuildingSettings></building>\n</buildings>\n</scene>\n";
    RenderScene scene = buildRenderScene(readSceneText(xml, "test.xml", test::testData()));
    MaterialId party = kNoMaterial;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].name == "party_wall") party = MaterialId(m);
    ASSERT_NE(party, kNoMaterial);
    size_t partyTriangles = 0;
    for (const BakedMesh &b : scene.meshes)
        for (size_t t = 0; t < b.mesh.triangleCount(); ++t) {
            if (b.mesh.triangleMaterials[t] != party) continue;
            ++partyTriangles;
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.mesh.positions[b.mesh.indices[3 * t + k]].x, 10.0f, 1e-3f);
        }
    EXPECT_GE(partyTriangles, 4u);  // each house's wall at x = 10
}

}  // namespace
}  // namespace veduta
