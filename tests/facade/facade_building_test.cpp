#include "facade/facade_building.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>

#include "thesis_figures.h"

namespace veduta {
namespace {

ModuleStructure module(std::string name, std::vector<Vec2d> outline, std::vector<double> storeys, RoofStructure roof) {
    ModuleStructure m;
    m.name = std::move(name);
    m.module.outline = std::move(outline);
    m.storeyHeights = std::move(storeys);
    m.roof = roof;
    return m;
}

RoofStructure gable(size_t edgeI, size_t edgeJ, double height) {
    RoofStructure r;
    r.general = {edgeI, edgeJ, 0.5, 0.5, 0, 1, height};
    return r;
}

// A 12 m × 10 m house of three storeys with a one-storey wing docked on the middle of its east
// wall, the wing's gable ridge running into that wall.
BuildingStructure houseWithWing() {
    BuildingStructure s;
    s.modules.push_back(module("Haus", {{0, 0}, {12, 0}, {12, 10}, {0, 10}}, {3, 3, 3}, gable(0, 2, 4)));
    s.modules.push_back(module("Flügel", {{0, 0}, {6, 0}, {6, 5}, {0, 5}}, {3}, gable(3, 1, 2)));
    s.docks.push_back({"Flügel", 3, "Haus", 1, 0.25, 0.75, {}});
    return s;
}

std::shared_ptr<const CorniceDescription> cornice() {
    return std::make_shared<CorniceDescription>(parseCorniceDescription(thesis::kFigure5_20Lines, "fig5_20"));
}

Style style(std::string name, MasonryStyle::Kind kind, double metresPerUnit) {
    Style s;
    s.name = std::move(name);
    s.walls = WallSubdivision{0.5, 0.6, 4};
    MasonryStyle masonry;
    masonry.kind = kind;
    if (kind == MasonryStyle::Kind::Bricks)
        masonry.bricks = std::make_shared<BrickBond>(parseBrickBond(thesis::kFigure5_7, "fig5_7"));
    masonry.metresPerUnit = metresPerUnit;
    s.masonry = masonry;
    WindowStyle window;
    window.placement = {1.2, 1.8, 1, 1, 0.9};
    for (EdgeCasing &e : window.casing.edges) e = {0.1, 0.05};
    s.windows[0] = window;
    s.bands = std::vector<BandStyle>{{0.9, 1.0, cornice(), {}}};
    s.materials[size_t(StylePart::Wall)] = s.name + "-wall";
    return s;
}

BuildingStyle oneStyle(Style s) {
    BuildingStyle b;
    b.bindings.building = s.name;
    b.styles.push_back(std::move(s));
    return b;
}

// Materials numbered in the order they are first asked for.
struct Materials {
    std::vector<std::string> names;
    MaterialByName byName() {
        return [this](const std::string &name, const FileLoc &) {
            auto it = std::find(names.begin(), names.end(), name);
            if (it == names.end()) it = names.insert(names.end(), name);
            return MaterialId(it - names.begin());
        };
    }
};

FacadeBuilding build(const BuildingStructure &s, const BuildingStyle &style, Materials &materials) {
    return buildFacadeBuilding(s, style, materials.byName(), 7, 1);
}

// The wall's stones, laid from its recipe.
std::vector<Stone> laidStones(const MasonryWall &w) {
    return w.recipe.lay ? w.recipe.lay(w.face).stones : w.masonry.stones;
}

size_t stoneCount(const FacadeBuilding &b) {
    size_t n = 0;
    for (const MasonryWall &w : b.masonry) n += laidStones(w).size();
    return n;
}

TEST(FacadeBuilding, OneStructureInTwoStylesKeepsItsHashAndChangesItsLook) {
    BuildingStructure s = houseWithWing();
    uint64_t before = structureHash(s);
    Materials m;
    FacadeBuilding brick = build(s, oneStyle(style("brick", MasonryStyle::Kind::Bricks, 0.12)), m);
    FacadeBuilding plain = build(s, oneStyle(style("plain", MasonryStyle::Kind::Plain, 1)), m);
    EXPECT_EQ(structureHash(s), before);
    EXPECT_GT(stoneCount(brick), 1000u);
    EXPECT_EQ(stoneCount(plain), 0u);
    EXPECT_TRUE(plain.masonry.empty());
    EXPECT_EQ(brick.openings, plain.openings);
    EXPECT_NE(std::find(m.names.begin(), m.names.end(), "brick-wall"), m.names.end());
    EXPECT_NE(std::find(m.names.begin(), m.names.end(), "plain-wall"), m.names.end());

    s.modules[0].storeyHeights[2] = 3.2;
    EXPECT_NE(structureHash(s), before);
}

TEST(FacadeBuilding, TheTriangleCountDoesNotDependOnTheBricks) {
    BuildingStructure s = houseWithWing();
    Materials m;
    FacadeBuilding large = build(s, oneStyle(style("a", MasonryStyle::Kind::Bricks, 0.12)), m);
    FacadeBuilding small = build(s, oneStyle(style("a", MasonryStyle::Kind::Bricks, 0.04)), m);
    EXPECT_GT(stoneCount(small), 5 * stoneCount(large));
    EXPECT_EQ(small.mesh.triangleCount(), large.mesh.triangleCount());
}

TEST(FacadeBuilding, MasonryTooFineForItsWallsIsRefusedWhenTheBuildingIsBuiltNotWhenItIsLaid) {
    // A shader lays the stones only when a ray first meets the wall, inside the render: what the
    // laying would refuse must be said while the building is built, at the description.
    Materials m;
    try {
        build(houseWithWing(), oneStyle(style("fine", MasonryStyle::Kind::Bricks, 0.001)), m);
        FAIL() << "a bond of 0.25 mm bricks was accepted";
    } catch (const InputError &e) {
        EXPECT_NE(std::string(e.what()).find("fig5_7:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("would lay more than"), std::string::npos) << e.what();
    }
}

TEST(FacadeBuilding, WindowsUnderTheLowerWingsRoofAreDroppedWithTheReason) {
    Materials m;
    FacadeBuilding b = build(houseWithWing(), oneStyle(style("a", MasonryStyle::Kind::Plain, 1)), m);
    ASSERT_FALSE(b.notes.empty());
    bool underRoof = std::any_of(b.notes.begin(), b.notes.end(), [](const std::string &note) {
        return note.find("storey 1: under the roof of module 'Flügel'") != std::string::npos;
    });
    EXPECT_TRUE(underRoof) << b.notes.front();

    // Without the wing nothing covers that wall, and no window is left out.
    BuildingStructure alone = houseWithWing();
    alone.modules.pop_back();
    alone.docks.clear();
    FacadeBuilding house = build(alone, oneStyle(style("a", MasonryStyle::Kind::Plain, 1)), m);
    EXPECT_TRUE(house.notes.empty()) << house.notes.front();
}

TEST(FacadeBuilding, TheHouseAloneHasOneWindowPerWallElementOnEveryStorey) {
    BuildingStructure s = houseWithWing();
    s.modules.pop_back();
    s.docks.clear();
    Materials m;
    FacadeBuilding b = build(s, oneStyle(style("a", MasonryStyle::Kind::Plain, 1)), m);
    // 12 m walls: 11 m free between corners, round((11 + 0.6) / 3) = 4 walls; 10 m walls: 3.
    EXPECT_EQ(b.openings, size_t(3 * 2 * (4 + 3)));
}

TEST(FacadeBuilding, WallTrianglesCarryWallCoordinatesInsideTheirFace) {
    Materials m;
    FacadeBuilding b = build(houseWithWing(), oneStyle(style("a", MasonryStyle::Kind::Bricks, 0.12)), m);
    ASSERT_FALSE(b.masonry.empty());
    for (const MasonryWall &wall : b.masonry) {
        ASSERT_FALSE(wall.triangles.empty());
        Vec2d low = wall.face.outline[0], high = wall.face.outline[2];
        for (uint32_t t : wall.triangles) {
            for (int k = 0; k < 3; ++k) {
                Vec2f uv = b.mesh.uvs[b.mesh.indices[3 * t + k]];
                EXPECT_GE(uv.x, low.x - 1e-4);
                EXPECT_LE(uv.x, high.x + 1e-4);
                EXPECT_GE(uv.y, low.y - 1e-4);
                EXPECT_LE(uv.y, high.y + 1e-4);
                EXPECT_NEAR(b.mesh.positions[b.mesh.indices[3 * t + k]].z, uv.y, 1e-4);
            }
        }
    }
}

TEST(FacadeBuilding, BandsBecomeClosedCorniceRingsAroundTheHouse) {
    BuildingStructure s = houseWithWing();
    s.modules.pop_back();
    s.docks.clear();
    Materials m;
    Style a = style("a", MasonryStyle::Kind::Plain, 1);
    a.materials[size_t(StylePart::Cornice)] = "cornice";
    FacadeBuilding b = build(s, oneStyle(a), m);
    MaterialId corniceId = MaterialId(std::find(m.names.begin(), m.names.end(), "cornice") - m.names.begin());
    ASSERT_LT(corniceId, m.names.size());
    std::set<float> heights;
    for (size_t t = 0; t < b.mesh.triangleCount(); ++t) {
        if (b.mesh.triangleMaterials[t] != corniceId) continue;
        for (int k = 0; k < 3; ++k) heights.insert(b.mesh.positions[b.mesh.indices[3 * t + k]].z);
    }
    // One band a storey, from 0.9 to 1.0 of it.
    ASSERT_FALSE(heights.empty());
    EXPECT_NEAR(*heights.begin(), 2.7f, 1e-4);
    EXPECT_NEAR(*heights.rbegin(), 9.0f, 1e-4);
}

TEST(FacadeBuilding, TheSameInputBuildsTheSameBuilding) {
    Materials m;
    BuildingStyle s = oneStyle(style("a", MasonryStyle::Kind::Bricks, 0.12));
    FacadeBuilding a = build(houseWithWing(), s, m), b = build(houseWithWing(), s, m);
    EXPECT_EQ(a.mesh.positions, b.mesh.positions);
    EXPECT_EQ(a.mesh.indices, b.mesh.indices);
    ASSERT_EQ(a.masonry.size(), b.masonry.size());
    for (size_t w = 0; w < a.masonry.size(); ++w) {
        EXPECT_EQ(a.masonry[w].recipe.hash, b.masonry[w].recipe.hash);
        std::vector<Stone> first = laidStones(a.masonry[w]), second = laidStones(b.masonry[w]);
        ASSERT_FALSE(first.empty());
        ASSERT_EQ(first.size(), second.size());
        for (size_t k = 0; k < first.size(); ++k) EXPECT_EQ(first[k].outline, second[k].outline);
    }
}

TEST(FacadeBuilding, TheModuleBindingOverridesTheBuildingsStyle) {
    BuildingStyle styles = oneStyle(style("brick", MasonryStyle::Kind::Bricks, 0.12));
    styles.styles.push_back(style("plain", MasonryStyle::Kind::Plain, 1));
    styles.bindings.modules["Flügel"] = "plain";
    Materials m;
    FacadeBuilding b = build(houseWithWing(), styles, m);
    ASSERT_FALSE(b.masonry.empty());
    MaterialId plainWall = MaterialId(std::find(m.names.begin(), m.names.end(), "plain-wall") - m.names.begin());
    ASSERT_LT(plainWall, m.names.size());
    for (const MasonryWall &w : b.masonry) EXPECT_NE(w.material, plainWall);
    EXPECT_NE(std::count(b.mesh.triangleMaterials.begin(), b.mesh.triangleMaterials.end(), plainWall), 0);
}

TEST(FacadeBuilding, ABindingToAMissingModuleIsRefused) {
    BuildingStyle styles = oneStyle(style("a", MasonryStyle::Kind::Plain, 1));
    styles.bindings.modules["Turm"] = "a";
    Materials m;
    EXPECT_THROW(build(houseWithWing(), styles, m), InputError);
}

TEST(StructureOnFootprint, ARectangleKeepsThePrototypesRoofOnTheFootprintsEdges) {
    ModuleStructure prototype = module("Haus", {{0, 0}, {1, 0}, {1, 1}}, {4, 3.5}, gable(1, 3, 4));
    prototype.subdivisions.push_back({0, 0.4, 0.6, 2, {}});
    // Counter-clockwise and clockwise, starting at different corners.
    for (const std::vector<Vec2d> &footprint : {std::vector<Vec2d>{{0, 0}, {14, 0}, {14, 12}, {0, 12}},
                                                std::vector<Vec2d>{{14, 0}, {0, 0}, {0, 12}, {14, 12}}}) {
        BuildingStructure s = structureOnFootprint(prototype, footprint, {});
        ASSERT_EQ(s.modules.size(), 1u);
        const ModuleStructure &m = s.modules[0];
        EXPECT_EQ(m.storeyHeights, prototype.storeyHeights);
        const std::vector<Vec2d> &o = m.module.outline;
        auto edgeOf = [&](size_t e) { return std::pair(o[e], o[(e + 1) % o.size()]); };
        // Footprint edge 1 and 3 are the sides x = 14 and x = 0 in both orders: the ridge runs along x.
        for (size_t e : {m.roof.general.edgeI, m.roof.general.edgeJ}) {
            auto [a, b] = edgeOf(e);
            EXPECT_EQ(a.x, b.x);
        }
        auto [a, b] = edgeOf(size_t(m.subdivisions[0].edge));
        EXPECT_EQ(a.y, 0);
        EXPECT_EQ(b.y, 0);
    }
}

TEST(StructureOnFootprint, AnLIsSplitIntoDockedModulesWithFlatRoofsThatBuild) {
    ModuleStructure prototype = module("Haus", {{0, 0}, {1, 0}, {1, 1}}, {3, 3}, gable(1, 3, 4));
    BuildingStructure s = structureOnFootprint(prototype, {{0, 0}, {20, 0}, {20, 8}, {8, 8}, {8, 20}, {0, 20}}, {});
    ASSERT_EQ(s.modules.size(), 2u);
    ASSERT_EQ(s.docks.size(), 1u);
    for (const ModuleStructure &m : s.modules) EXPECT_EQ(m.roof.kind, RoofStructure::Kind::Flat);
    Materials materials;
    FacadeBuilding b = build(s, oneStyle(style("a", MasonryStyle::Kind::Plain, 1)), materials);
    EXPECT_GT(b.openings, 0u);
}

TEST(StructureOnFootprint, ASlotNoStyleFillsLeavesThePartyWallsBlank) {
    ModuleStructure prototype = module("Haus", {{0, 0}, {1, 0}, {1, 1}}, {3, 3}, gable(1, 3, 4));
    prototype.subdivisions = {{1, 0, 1, 9, {}}, {3, 0, 1, 9, {}}};
    Materials materials;
    BuildingStyle plain = oneStyle(style("a", MasonryStyle::Kind::Plain, 1));
    FacadeBuilding row =
        build(structureOnFootprint(prototype, {{-10, 8}, {6, 8}, {6, 22}, {-10, 22}}, {}), plain, materials);
    // 16 m front and back: round((14.4 + 0.6) / 3) = 5 walls a storey; the 14 m sides none.
    EXPECT_EQ(row.openings, size_t(2 * 2 * 5));
}

}  // namespace
}  // namespace veduta
