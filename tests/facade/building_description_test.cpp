#include "facade/building_description.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "facade/casings.h"
#include "facade/floor_plan.h"
#include "facade/general_roof.h"
#include "input_error.h"
#include "test_paths.h"

namespace veduta {
namespace {

using test::inputErrorOf;

std::string palaceFile(const std::string &name) {
    std::ifstream in(test::sourceDir() / "scenes" / "palace" / name, std::ios::binary);
    EXPECT_TRUE(in) << name;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A readFile that serves the palace's files and counts how often each is read.
struct PalaceFiles {
    std::map<std::string, int> reads;
    DescribedFileReader reader() {
        return [this](const std::string &name, const FileLoc &) {
            ++reads[name];
            return palaceFile(name);
        };
    }
};

BuildingStructure palaceStructure() {
    return parseBuildingStructure(palaceFile("palace.structure"), "palace.structure");
}

const ModuleStructure &moduleNamed(const BuildingStructure &s, const std::string &name) {
    return s.modules[size_t(s.moduleIndex(name, {}))];
}

std::string structureError(const std::string &text) {
    return inputErrorOf([&] { parseBuildingStructure(text, "t.structure"); });
}

// A small valid structure that the error tests vary.
const std::string kBox = "Module { \"A\"; 0, 0; 10, 0; 10, 8; 0, 8; }\nStoreys { \"A\"; 3; }\n";

std::string styleError(const std::string &text) {
    return inputErrorOf([&] {
        parseBuildingStyle(text, "t.style", [](const std::string &name, const FileLoc &loc) -> std::string {
            if (name == "bad.ashlar") return "AshlarMasonry { 1, 1, 0; 2, 1, 0; 9, 9, 9; 9, 9, 9; 0.1; 300, 0, 0; }";
            throw InputError(loc, "cannot read " + name);
        });
    });
}

const Style &styleNamed(const BuildingStyle &s, const std::string &name) { return s.style(name, {}); }

TEST(BuildingStructureText, ThePalaceHasItsModulesStoreysDocksRoofsAndSlots) {
    BuildingStructure palace = palaceStructure();
    ASSERT_EQ(palace.modules.size(), 4u);
    EXPECT_EQ(palace.storeyCount(), 5u);
    const ModuleStructure &corps = moduleNamed(palace, "Corps");
    EXPECT_EQ(corps.module.type, "Corps de logis");
    EXPECT_EQ(corps.storeyHeights, (std::vector<double>{4.5, 5.0, 4.0, 4.0, 3.8}));
    EXPECT_DOUBLE_EQ(corps.module.height, 21.3);
    EXPECT_EQ(corps.module.wallThickness, 0);
    EXPECT_EQ(moduleNamed(palace, "Risalit").storeyHeights, corps.storeyHeights);
    EXPECT_EQ(moduleNamed(palace, "East wing").storeyHeights.size(), 3u);
    EXPECT_EQ(moduleNamed(palace, "West wing").storeyHeights.size(), 3u);

    // The corps and the wings have hip roofs along their length, the risalit a front gable.
    const GeneralRoofParameters &hip = corps.roof.general;
    EXPECT_EQ(corps.roof.kind, RoofStructure::Kind::General);
    EXPECT_EQ(hip.edgeI, 3u);
    EXPECT_EQ(hip.edgeJ, 1u);
    EXPECT_EQ(hip.a, 0.2);
    EXPECT_EQ(hip.b, 0.8);
    EXPECT_EQ(hip.height, 6);
    const GeneralRoofParameters &gable = moduleNamed(palace, "Risalit").roof.general;
    EXPECT_EQ(gable.edgeI, 0u);
    EXPECT_EQ(gable.edgeJ, 2u);
    EXPECT_EQ(gable.a, 0);
    EXPECT_EQ(gable.b, 1);
    EXPECT_EQ(gable.height, 3);
    for (const char *wing : {"East wing", "West wing"}) {
        EXPECT_EQ(moduleNamed(palace, wing).roof.general.a, 0.25);
        EXPECT_EQ(moduleNamed(palace, wing).roof.general.b, 0.75);
    }

    ASSERT_EQ(palace.docks.size(), 3u);
    const ModuleDock &risalit = palace.docks[0];
    EXPECT_EQ(risalit.docked, "Risalit");
    EXPECT_EQ(risalit.dockedEdge, 2);
    EXPECT_EQ(risalit.dominant, "Corps");
    EXPECT_EQ(risalit.edge, 0);
    EXPECT_NEAR(risalit.a, 1.0 / 3, 1e-15);
    EXPECT_NEAR(risalit.b, 2.0 / 3, 1e-15);
    EXPECT_EQ(risalit.loc.toString(), "palace.structure:14:8");

    const std::vector<EdgeSubdivision> &front = moduleNamed(palace, "Risalit").subdivisions;
    ASSERT_EQ(front.size(), 3u);
    EXPECT_EQ(front[1].edge, 0);
    EXPECT_EQ(front[1].from, 0.35);
    EXPECT_EQ(front[1].to, 0.65);
    EXPECT_EQ(front[1].slot, 2);
    EXPECT_EQ(front[0].slot, 3);
    EXPECT_EQ(front[2].slot, 3);
    EXPECT_TRUE(corps.subdivisions.empty());
}

TEST(BuildingStructureText, ThePalaceDocksIntoAValidFloorPlan) {
    BuildingStructure palace = palaceStructure();
    std::vector<FloorPlanModule> modules;
    for (const ModuleStructure &m : palace.modules) modules.push_back(m.module);
    std::vector<KkConnection> docks;
    for (const ModuleDock &d : palace.docks)
        docks.push_back({false, palace.moduleIndex(d.dominant, d.loc), d.edge, palace.moduleIndex(d.docked, d.loc),
                         d.dockedEdge, d.a, d.b, d.loc});
    FloorPlan plan(modules, docks, {});
    // The risalit stands 4 m in front of the middle third of the corps' front, the wings 20 m
    // beside its ends, unscaled.
    const std::vector<Vec2d> &risalit = plan.modules()[1].outline;
    EXPECT_NEAR(risalit[0].x, 12, 1e-9);
    EXPECT_NEAR(risalit[0].y, -4, 1e-9);
    EXPECT_NEAR(risalit[2].x, 24, 1e-9);
    EXPECT_NEAR(risalit[2].y, 0, 1e-9);
    EXPECT_NEAR(plan.modules()[2].outline[1].x, 56, 1e-9);
    EXPECT_NEAR(plan.modules()[2].outline[1].y, 1.5, 1e-9);
    EXPECT_NEAR(plan.modules()[3].outline[0].x, -20, 1e-9);
    EXPECT_NEAR(plan.modules()[3].outline[2].y, 13.5, 1e-9);
    // Every roof of the palace can be built over its module.
    for (const ModuleStructure &m : palace.modules)
        EXPECT_NO_THROW(generalRoof(m.module.outline, m.height(), std::vector<bool>(4, false), m.roof.general))
            << m.name;
}

TEST(BuildingStructureText, RoofShorthandsGiveTheParametersOfRow5) {
    // digest §8 row 5: the unit square, e_i bottom (0), e_j top (2), c = d = 0.5, h = 1.
    auto roofOf = [](const std::string &roof) {
        return parseBuildingStructure(
                   "Module { \"U\"; 0, 0; 1, 0; 1, 1; 0, 1; } Storeys { \"U\"; 3; } Roof { \"U\"; " + roof + "; }",
                   "u.structure")
            .modules[0]
            .roof;
    };
    auto expectRoof = [](const RoofStructure &roof, size_t i, size_t j, double c, double d, double a, double b) {
        EXPECT_EQ(roof.kind, RoofStructure::Kind::General);
        EXPECT_EQ(roof.general.edgeI, i);
        EXPECT_EQ(roof.general.edgeJ, j);
        EXPECT_EQ(roof.general.c, c);
        EXPECT_EQ(roof.general.d, d);
        EXPECT_EQ(roof.general.a, a);
        EXPECT_EQ(roof.general.b, b);
        EXPECT_EQ(roof.general.height, 1);
    };
    expectRoof(roofOf("gable, 0, 2, 1"), 0, 2, 0.5, 0.5, 0, 1);
    expectRoof(roofOf("pyramid, 0, 2, 1"), 0, 2, 0.5, 0.5, 0.5, 0.5);
    expectRoof(roofOf("hip, 0, 2, 1, 0.2"), 0, 2, 0.5, 0.5, 0.2, 0.8);
    expectRoof(roofOf("shed, 2, 1"), 2, 2, 0, 1, 0, 1);
    expectRoof(roofOf("general, 0, 2, 0.5, 0.5, 0.2, 0.8, 1"), 0, 2, 0.5, 0.5, 0.2, 0.8);

    // The shed's one vertical quad stands on its edge; the pyramid's apex is (0.5, 0.5, 1) over the eaves.
    RoofStructure shed = roofOf("shed, 2, 1");
    ModuleRoof built = generalRoof({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, std::vector<bool>(4, false), shed.general);
    int quads = 0;
    for (const ModuleRoofFace &face : built.faces)
        if (face.kind == RoofFaceKind::Interface && face.corners.size() == 4) {
            ++quads;
            EXPECT_EQ(face.edge, 2u);
        }
    EXPECT_EQ(quads, 1);
    ModuleRoof pyramid = generalRoof({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, std::vector<bool>(4, false),
                                     roofOf("pyramid, 0, 2, 1").general);
    ASSERT_TRUE(pyramid.ridge);
    EXPECT_NEAR(pyramid.ridge->a.x, 0.5, 1e-12);
    EXPECT_NEAR(pyramid.ridge->a.y, 0.5, 1e-12);
    EXPECT_NEAR(pyramid.ridge->a.z, 1, 1e-12);

    RoofStructure flat = roofOf("flat, 1.1, 0.4");
    EXPECT_EQ(flat.kind, RoofStructure::Kind::Flat);
    EXPECT_EQ(flat.parapet.height, 1.1);
    EXPECT_EQ(flat.parapet.width, 0.4);
}

TEST(BuildingStructureText, AModuleWithoutARoofGetsAFlatRoofWithAParapet) {
    RoofStructure roof = parseBuildingStructure(kBox, "t.structure").modules[0].roof;
    EXPECT_EQ(roof.kind, RoofStructure::Kind::Flat);
    EXPECT_EQ(roof.parapet.height, 1);
    EXPECT_EQ(roof.parapet.width, 0.3);
    EXPECT_EQ(roof.loc.toString(), "t.structure:1:1");
}

TEST(BuildingStructureText, RepeatedStoreysExpand) {
    BuildingStructure s = parseBuildingStructure(
        "Module { \"A\"; 0, 0; 10, 0; 10, 8; }\nStoreys { \"A\"; 4.5; 4.0, 3; 3.2; }", "t.structure");
    EXPECT_EQ(s.modules[0].storeyHeights, (std::vector<double>{4.5, 4, 4, 4, 3.2}));
}

TEST(BuildingStructureText, TheHashIgnoresLayoutAndCommentsButNotNumbers) {
    std::string text = palaceFile("palace.structure");
    uint64_t hash = structureHash(palaceStructure());
    std::string respaced;
    bool comment = false, quoted = false;
    for (char c : text) {
        if (c == '"' && !comment) quoted = !quoted;
        if (c == '#' && !quoted) comment = true;
        if (c == '\n') comment = false;
        if (comment) continue;
        if (quoted) respaced += c;
        else if (c == ' ') respaced += "\t ";
        else if (c == ';') respaced += " ;\n# a note\n";
        else respaced += c;
    }
    ASSERT_NE(respaced, text);
    EXPECT_EQ(structureHash(parseBuildingStructure(respaced, "other.structure")), hash);
    std::string changed = text;
    size_t at = changed.find("hip, 3, 1, 4.5, 0.25");
    ASSERT_NE(at, std::string::npos);
    changed.replace(at, 20, "hip, 3, 1, 4.5, 0.26");
    EXPECT_NE(structureHash(parseBuildingStructure(changed, "palace.structure")), hash);
}

TEST(BuildingStructureText, ErrorsNameTheirPlace) {
    EXPECT_EQ(structureError("Modul { \"A\"; 0, 0; }"),
              "t.structure:1:1: unknown block 'Modul' (Module, Storeys, Roof, Dock or Windows)");
    EXPECT_EQ(structureError("# nothing\n"), "t.structure:1:1: the structure has no Module block");
    EXPECT_EQ(structureError("Module { \"A\"; 0, 0; 10, 0; 10, 8; }"),
              "t.structure:1:1: the module 'A' has no Storeys block");
    EXPECT_EQ(structureError(kBox + "Storeys { \"B\"; 3; }"), "t.structure:3:11: no module named 'B'");
    EXPECT_EQ(structureError(kBox + "Storeys { \"A\";\n 3; }"),
              "t.structure:3:1: a second Storeys block for 'A' (the first is at t.structure:2:1)");
    EXPECT_EQ(structureError(kBox + "Module { \"A\"; 0, 0; 1, 0; 1, 1; }"),
              "t.structure:3:10: a second module named 'A' (the first is at t.structure:1:1)");
    EXPECT_EQ(structureError(kBox + "Roof { \"A\"; hip, 4, 1, 3, 0.2; }"),
              "t.structure:3:18: the roof's edge e_i 4 is outside [0, 3]");
    EXPECT_EQ(structureError(kBox + "Roof { \"A\"; hip, 3, 1, 3, 0.5; }"),
              "t.structure:3:27: the hip's inset 0.5 must lie between 0 (a gable) and 0.5 (a pyramid)");
    EXPECT_EQ(structureError(kBox + "Roof { \"A\"; gable, 0, 2; }"),
              "t.structure:3:13: a gable roof (gable, e_i, e_j, h) takes 4 fields, found 3");
    EXPECT_EQ(structureError(kBox + "Roof { \"A\"; mansard, 0, 2, 1; }"),
              "t.structure:3:13: unknown roof 'mansard' (general, gable, hip, pyramid, shed or flat)");
    EXPECT_EQ(structureError(kBox + "Roof { \"A\"; gable, 1, 1, 1; }"),
              "t.structure:3:13: the ridge's chord from e_i[c] to e_j[d] has no length");
    EXPECT_EQ(structureError("Module { \"A\"; 0, 0; 10, 0; 10, 8; }\nStoreys { \"A\"; 0.4; }"),
              "t.structure:2:16: a storey height 0.4 is outside [0.5, 100]");
    EXPECT_EQ(structureError("Module { \"A\"; 0, 0; 10, 0; 10, 8; }\nStoreys { \"A\"; 3, 150; 3, 51; }"),
              "t.structure:2:24: a module has at most 200 storeys");
    EXPECT_EQ(structureError(kBox +
                             "Module { \"B\"; 0, 0; 5, 0; 5, 5; }\nStoreys { \"B\"; 3; }\n"
                             "Dock { \"B\", 0, \"A\", 0, 0.5, 0.5; }"),
              "t.structure:5:29: the dock's b 0.5 is not above its a 0.5");
    EXPECT_EQ(structureError(kBox + "Dock { \"A\", 0, \"A\", 1, 0, 1; }"),
              "t.structure:3:16: the module 'A' is docked onto itself");
    EXPECT_EQ(structureError(kBox + "Windows { \"A\"; 1, 0, 0.5, 1000; }"),
              "t.structure:3:27: the window slot 1000 is outside [0, 999]");
    EXPECT_EQ(structureError(kBox + "Windows { \"A\"; 1, 0.5, 0.5, 1; }"),
              "t.structure:3:24: the part's end 0.5 is not after its start 0.5");
    EXPECT_EQ(structureError("Module { \"A\"; 0, 0; 1e5, 0; 10, 8; }"),
              "t.structure:1:21: x 1e5 is outside [-10000, 10000]");
    // The lead's validation runs last, with the subdivision's place.
    EXPECT_EQ(structureError(kBox + "Windows { \"A\"; 1, 0, 0.6, 1; 1, 0.5, 1, 2; }"),
              "t.structure:3:30: the part [0.5, 1] of edge 1 overlaps [0, 0.6] at t.structure:3:16");
}

TEST(BuildingStyleText, TheClassicalStyleBindsAllThreeLevels) {
    PalaceFiles files;
    BuildingStyle style = parseBuildingStyle(palaceFile("classical.style"), "classical.style", files.reader());
    ASSERT_EQ(style.styles.size(), 5u);
    EXPECT_EQ(style.bindings.building, "classical");
    EXPECT_EQ(style.bindings.storeys, (std::map<int, std::string>{{0, "rusticated"}, {2, "wing eaves"}, {4, "attic"}}));
    EXPECT_EQ(style.bindings.modules, (std::map<std::string, std::string>{{"Risalit", "risalit"}}));

    const Style &classical = styleNamed(style, "classical");
    ASSERT_TRUE(classical.walls);
    EXPECT_EQ(classical.walls->cornerWidth, 0.9);
    EXPECT_EQ(classical.walls->interWallWidth, 0.7);
    EXPECT_EQ(classical.walls->wallToInterWallRatio, 4);
    ASSERT_TRUE(classical.masonry);
    EXPECT_EQ(classical.masonry->kind, MasonryStyle::Kind::Plain);
    const WindowStyle &window = classical.windows.at(0);
    EXPECT_EQ(window.kind, OpeningKind::Window);
    EXPECT_EQ(window.placement.width, 1.3);
    EXPECT_EQ(window.placement.height, 2.4);
    EXPECT_EQ(window.placement.sillHeight, 0.9);
    EXPECT_EQ(window.casing.style, CasingStyle::Gesims);
    EXPECT_EQ(window.refinement[kTop].size, 0.12);
    EXPECT_TRUE(window.refinement[kTop].profile.empty());
    EXPECT_EQ(window.refinement[kBottom].size, 0);
    for (const EdgeCasing &edge : window.casing.edges) {
        EXPECT_EQ(edge.thickness, 0.08);
        EXPECT_EQ(edge.overhang, 0.06);
    }
    EXPECT_EQ(window.frame.thickness, 0.06);
    EXPECT_EQ(window.frame.overhang, -0.05);
    EXPECT_EQ(window.frame.paneDepth, -0.12);
    const WindowStyle &pediment = classical.windows.at(2);
    EXPECT_EQ(pediment.casing.style, CasingStyle::Doppelgesims);
    EXPECT_EQ(pediment.refinement[kTop].profile, (std::vector<Vec2d>{{0.5, 1}}));
    EXPECT_EQ(classical.materials[size_t(StylePart::RoofSide)], "palace-roof-side");
    EXPECT_EQ(classical.materials[size_t(StylePart::Wall)], "palace-plaster");

    const Style &rusticated = styleNamed(style, "rusticated");
    ASSERT_TRUE(rusticated.masonry);
    EXPECT_EQ(rusticated.masonry->kind, MasonryStyle::Kind::Ashlar);
    EXPECT_EQ(rusticated.masonry->metresPerUnit, 0.01);
    ASSERT_TRUE(rusticated.masonry->ashlar);
    EXPECT_EQ(rusticated.masonry->ashlar->minSize.height, 45);
    const WindowStyle &door = rusticated.windows.at(2);
    EXPECT_EQ(door.kind, OpeningKind::Door);
    EXPECT_EQ(door.placement.sillHeight, 0);
    EXPECT_EQ(door.casing.edges[kBottom].thickness, 0);  // no casing across the threshold
    EXPECT_EQ(door.casing.edges[kTop].thickness, 0.06);

    // Bands: the string course is one description, shared by every style that names it.
    ASSERT_TRUE(classical.bands && styleNamed(style, "attic").bands && styleNamed(style, "wing eaves").bands);
    const std::vector<BandStyle> &eaves = *styleNamed(style, "wing eaves").bands;
    ASSERT_EQ(eaves.size(), 2u);
    EXPECT_EQ(eaves[1].vStart, 0.86);
    EXPECT_EQ(eaves[1].vStop, 1);
    EXPECT_EQ(eaves[0].cornice, classical.bands->at(0).cornice);
    EXPECT_EQ(eaves[1].cornice, styleNamed(style, "attic").bands->at(1).cornice);
    EXPECT_NE(eaves[0].cornice, eaves[1].cornice);
    EXPECT_FALSE(styleNamed(style, "risalit").bands);
    EXPECT_EQ(
        files.reads,
        (std::map<std::string, int>{
            {"main.cornice", 1}, {"plinth.cornice", 1}, {"rustication.ashlar", 1}, {"string_course.cornice", 1}}));
}

TEST(BuildingStyleText, TheRisalitsGroundStoreyMiddleIsADoor) {
    PalaceFiles files;
    BuildingStyle style = parseBuildingStyle(palaceFile("classical.style"), "classical.style", files.reader());
    BuildingStructure palace = palaceStructure();
    std::vector<std::string> names;
    for (const ModuleStructure &m : palace.modules) names.push_back(m.name);
    checkBindings(style, names, palace.storeyCount());
    ResolvedStyle ground = resolveStyle(style, "Risalit", 0), first = resolveStyle(style, "Risalit", 1);
    ASSERT_TRUE(ground.window(2) && first.window(2) && ground.window(3));
    EXPECT_EQ(ground.window(2)->kind, OpeningKind::Door);
    EXPECT_EQ(first.window(2)->kind, OpeningKind::Window);
    EXPECT_EQ(ground.window(3)->casing.style, CasingStyle::Doppelgesims);
    ASSERT_TRUE(ground.masonry);
    EXPECT_EQ(ground.masonry->kind, MasonryStyle::Kind::Ashlar);
    EXPECT_FALSE(first.masonry);  // plain
    EXPECT_EQ(resolveStyle(style, "Corps", 4).bands.size(), 2u);
    EXPECT_EQ(resolveStyle(style, "Corps", 0).material(StylePart::Wall), "palace-stone");
    EXPECT_EQ(resolveStyle(style, "Corps", 1).material(StylePart::Wall), "palace-plaster");
}

TEST(BuildingStyleText, TheBrickStyleLaysACrossBondWithoutBands) {
    PalaceFiles files;
    BuildingStyle style = parseBuildingStyle(palaceFile("brick.style"), "brick.style", files.reader());
    ASSERT_EQ(style.styles.size(), 3u);
    EXPECT_EQ(style.bindings.building, "brick");
    EXPECT_EQ(style.bindings.storeys.at(0), "brick ground");
    EXPECT_EQ(style.bindings.modules.at("Risalit"), "brick risalit");
    const Style &brick = styleNamed(style, "brick");
    ASSERT_TRUE(brick.masonry && brick.masonry->bricks);
    EXPECT_EQ(brick.masonry->kind, MasonryStyle::Kind::Bricks);
    EXPECT_EQ(brick.masonry->metresPerUnit, 0.01);
    const BrickBond &bond = *brick.masonry->bricks;
    ASSERT_EQ(bond.courses.size(), 4u);
    // Stretchers and headers alternate, the headers a quarter stretcher off, every second
    // stretcher course half a stretcher (24 cm + 1 cm joint) off.
    EXPECT_DOUBLE_EQ(bond.courses[0].offset, 0);
    EXPECT_DOUBLE_EQ(bond.courses[1].offset, 6.25);
    EXPECT_DOUBLE_EQ(bond.courses[2].offset, 12.5);
    EXPECT_DOUBLE_EQ(bond.courses[3].offset, 6.25);
    EXPECT_DOUBLE_EQ(bond.courses[0].length, 25);
    EXPECT_DOUBLE_EQ(bond.courses[1].length, 12.5);
    EXPECT_EQ(bond.bricks[0].size.length, 24);
    EXPECT_EQ(bond.bricks[0].size.height, 7.1);
    EXPECT_EQ(bond.mortarThickness, 1);
    ASSERT_TRUE(brick.bands);
    EXPECT_TRUE(brick.bands->empty());
    for (const Style &s : style.styles)
        for (const auto &[slot, window] : s.windows) EXPECT_EQ(window.casing.style, CasingStyle::Klinker) << slot;
    EXPECT_EQ(files.reads, (std::map<std::string, int>{{"cross_bond.bricks", 1}}));
}

TEST(BuildingStyleText, ThePalaceStylesBuildEveryOpeningAndCornice) {
    for (const char *file : {"classical.style", "brick.style"}) {
        PalaceFiles files;
        BuildingStyle style = parseBuildingStyle(palaceFile(file), file, files.reader());
        for (const Style &s : style.styles) {
            for (const auto &[slot, window] : s.windows) {
                // On a 4 m wide wall of the lowest storey (3.8 m), as the palace has.
                WallQuad wall = WallQuad::rectangle({0, 0}, {4, 3.8});
                RefinedOpening opening = refineOpening(placeOpening(wall, window.placement), window.refinement,
                                                       window.dominance, window.kind);
                EXPECT_NO_THROW(buildOpeningPieces(opening, window.casing, window.frame)) << s.name << " " << slot;
            }
            for (const BandStyle &band : s.bands.value_or(std::vector<BandStyle>{})) {
                ProfileOutline outline = traceProfile(band.cornice->profile, 10);
                EXPECT_NO_THROW(heightScale(band.cornice->profile, outline, (band.vStop - band.vStart) * 3.8));
            }
        }
    }
}

TEST(BuildingStyleText, APalaceDescriptionIsAboutAHundredKilobytesOrLess) {
    // digest §8 row 21 (L1562: ~200 kB of XML for a five-storey building and its style).
    PalaceFiles files;
    std::string structure = palaceFile("palace.structure"), style = palaceFile("classical.style");
    parseBuildingStyle(style, "classical.style", files.reader());
    size_t bytes = structure.size() + style.size();
    for (const auto &[name, reads] : files.reads) bytes += palaceFile(name).size();
    std::printf("the palace (structure, classical style, %zu named files) takes %zu bytes\n", files.reads.size(),
                bytes);
    EXPECT_LE(bytes, 100u * 1024);
    EXPECT_GE(files.reads.size(), 4u);
}

TEST(BuildingStyleText, ErrorsNameTheirPlace) {
    const std::string bind = "\nBind { building, \"s\"; }";
    EXPECT_EQ(styleError("Style { \"s\"; walls, 1, 1, 4; walls, 1, 1, 3; }" + bind),
              "t.style:1:30: a second walls item (the first is at t.style:1:14)");
    EXPECT_EQ(styleError("Style { \"s\"; casing, 0, einfach, 0, 0.1, 0; }" + bind),
              "t.style:1:22: a casing for slot 0, which has no window or door in the style 's'");
    EXPECT_EQ(styleError("Style { \"s\"; window, 0, 1, 2, 1, 1, 1;\n frame, 1, 0.1, 0, -0.1; }" + bind),
              "t.style:2:9: a frame for slot 1, which has no window or door in the style 's'");
    EXPECT_EQ(styleError("Style { \"s\"; door, 0, 1, 2, 1, 1;\n casing, 0, doppelgesims, 0.1, 0.1, 0; }" + bind),
              "t.style:2:27: a doppelgesims needs a band at least twice its thickness 0.1 for its gable, not 0.1");
    EXPECT_EQ(styleError("Style { \"s\"; door, 0, 1, 2, 1, 1;\n casing, 0, einfach, 0.1, 0.1, 0; }" + bind),
              "t.style:2:22: a casing 'einfach' has no band: its size must be 0");
    EXPECT_EQ(styleError("Style { \"s\"; window, 0, 1, 2, 1, 1, 1; door, 0, 1, 2, 1, 1; }" + bind),
              "t.style:1:40: a second window or door for slot 0 (the first is at t.style:1:14)");
    EXPECT_EQ(styleError("Style { \"s\"; window, 1000, 1, 2, 1, 1, 1; }" + bind),
              "t.style:1:22: the slot 1000 is outside [0, 999]");
    EXPECT_EQ(styleError("Style { \"s\"; material, roofs, \"x\"; }" + bind),
              "t.style:1:24: unknown part 'roofs' (wall, casing, cornice, frame, pane, door, roof, roof-side, parapet, "
              "interior)");
    EXPECT_EQ(styleError("Style { \"s\"; bands, none; band, 0, 0.1, \"c\"; }" + bind),
              "t.style:1:27: a band beside 'bands, none' at t.style:1:14");
    EXPECT_EQ(styleError("Style { \"s\"; masonry, ashlar, \"a\", 0.01; }" + bind), "t.style:1:31: cannot read a");
    EXPECT_EQ(styleError("Style { \"s\"; masonry, ashlar, \"bad.ashlar\", 0.01; }" + bind),
              "bad.ashlar:1:58: the mortar colour: 300 is not a whole number from 0 to 255");
    EXPECT_EQ(styleError("Style { \"s\"; masonry, stone; }" + bind),
              "t.style:1:23: unknown masonry 'stone' (plain, bricks, ashlar or cyclopean)");
    EXPECT_EQ(styleError("Style { \"s\"; window, 0, 1, 2, 1, 0, 0; }" + bind),
              "t.style:1:37: the distances left and right are both 0 (their ratio places it)");
    EXPECT_EQ(styleError("Style { \"s\"; }"), "t.style:1:1: the style has no Bind block");
    EXPECT_EQ(styleError("Style { \"s\"; }" + bind + bind),
              "t.style:3:1: a second Bind block (the first is at t.style:2:1)");
    EXPECT_EQ(styleError("Style { \"s\"; }\nBind { storey, 0, \"s\"; }"),
              "t.style:2:1: the Bind block binds no building style (building, \"style\")");
    EXPECT_EQ(styleError("Style { \"s\"; }\nBind { building, \"s\"; module, \"A\", \"t\"; }"),
              "t.style:2:36: no style named 't'");
    EXPECT_EQ(styleError("Style { \"s\"; }\nStyle { \"s\"; }" + bind),
              "t.style:2:9: a second style named 's' (the first is at t.style:1:1)");
    EXPECT_EQ(styleError("Stil { \"s\"; }" + bind), "t.style:1:1: unknown block 'Stil' (Style or Bind)");
    EXPECT_EQ(styleError("Style { \"s\"; door, 0, 1, 2, 1, 1; apron, 0, 0.5, 0.03; }" + bind),
              "t.style:1:42: a door has no apron below it");
    EXPECT_EQ(styleError("Style { \"s\"; window, 0, 1, 2, 1, 1, 1; apron, 0, 0.05, 0.03; }" + bind),
              "t.style:1:50: the apron's height 0.05 is outside [0.1, 10]");
    EXPECT_EQ(styleError("Style { \"s\"; window, 0, 1, 2, 1, 1, 1; apron, 0, 0.5; }" + bind),
              "t.style:1:40: an apron (apron, slot, height, depth) takes 4 fields, found 3");
}

TEST(BuildingStyleText, AnApronBelongsToItsSlotsWindow) {
    BuildingStyle style = parseBuildingStyle(
        "Style { \"s\"; window, 2, 1.2, 2, 0.9, 1, 1; apron, 2, 0.5, 0.03; }\nBind { building, \"s\"; }", "t.style",
        [](const std::string &, const FileLoc &) { return std::string(); });
    const WindowStyle &window = style.styles[0].windows.at(2);
    ASSERT_TRUE(window.apron);
    EXPECT_EQ(window.apron->height, 0.5);
    EXPECT_EQ(window.apron->depth, 0.03);
    EXPECT_EQ(window.apron->loc.toString(), "t.style:1:44");
}

TEST(BuildingStyleText, AFileNamedByTwoStylesIsReadAndParsedOnce) {
    int reads = 0;
    BuildingStyle style = parseBuildingStyle(
        "Style { \"a\"; band, 0, 0.1, \"c\"; masonry, cyclopean, \"z\"; }\n"
        "Style { \"b\"; band, 0.2, 0.3, \"c\"; band, 0.4, 0.5, \"c\"; masonry, cyclopean, \"z\"; }\n"
        "Bind { building, \"a\"; storey, 1, \"b\"; }",
        "t.style", [&](const std::string &name, const FileLoc &) -> std::string {
            ++reads;
            if (name == "z") return "CyclopeanMasonry { stones, 40; 10; 0,0,0; 255,255,255; 0.02; 9,9,9; 0.01; }";
            return "Modifications { line, rel, 90, 1; line, rel, -90, 1; }";
        });
    EXPECT_EQ(reads, 2);
    const Style &a = style.styles[0], &b = style.styles[1];
    EXPECT_EQ(a.bands->at(0).cornice, b.bands->at(1).cornice);
    EXPECT_EQ(b.bands->at(0).cornice, b.bands->at(1).cornice);
    EXPECT_EQ(a.masonry->cyclopean, b.masonry->cyclopean);
    EXPECT_EQ(a.masonry->cyclopean->stones, 40);
}

}  // namespace
}  // namespace veduta
