// Finkenzeller's small languages (docs/facades.md) on any text: the text read as a cornice
// description, a brick bond, an ashlar and a cyclopean description, a building structure and a
// building style. What reads is then used as a facade uses it, on a small wall with a window and
// round a small rectangle, skipping only what would be too fine to finish quickly (the readers'
// own limits allow a million bricks, which is correct but slow per input). A style's named files
// are small valid texts of their kind, or the input itself where it names "input". Bad input must
// be an InputError, whichever step finds it.
#include <string>
#include <vector>

#include "facade/ashlar.h"
#include "facade/brick_bond.h"
#include "facade/building_description.h"
#include "facade/consoles.h"
#include "facade/cyclopean.h"
#include "facade/floor_plan.h"
#include "facade/profile.h"
#include "facade/profile_sweep.h"
#include "fuzz_input.h"

namespace {

using namespace veduta;

constexpr double kMetresPerUnit = 0.1;
constexpr double kLeastStoneArea = 1.2 * 1.0 / 5000;  // the wall's area over the most stones we lay

WallFace smallWall() {
    return {{{0, 0}, {1.2, 0}, {1.2, 1.0}, {0, 1.0}}, {{{0.35, 0.3}, {0.8, 0.3}, {0.8, 0.85}, {0.35, 0.85}}}};
}

void layBond(const BrickBond &bond) {
    for (const BrickKind &brick : bond.bricks)
        if (brick.size.length * brick.size.height * kMetresPerUnit * kMetresPerUnit < kLeastStoneArea) return;
    layBrickBond(bond, smallWall(), {kMetresPerUnit, 7, 1});
}

void layStones(const AshlarMasonry &ashlar) {
    if (ashlar.minSize.length * ashlar.minSize.height * kMetresPerUnit * kMetresPerUnit < kLeastStoneArea) return;
    layAshlar(ashlar, smallWall(), {kMetresPerUnit, 7, 1});
}

void layCyclopean(const CyclopeanMasonry &cyclopean) {
    // At most a few dozen stones and relaxation steps: enough to reach every step of the layout.
    if (cyclopean.lloyd > 20 || cyclopean.stones > 50 || (cyclopean.spacing > 0 && cyclopean.spacing < 0.15)) return;
    cyclopeanMasonry(smallWall(), cyclopean, 7, 1);
}

// A style's named file: the input where it names "input", else a small valid text of the kind
// its name ends with.
std::string namedFile(const std::string &name, const std::string &input) {
    auto endsWith = [&](std::string_view end) { return name.ends_with(end); };
    if (name == "input") return input;
    if (endsWith(".bricks"))
        return R"(B { 2.0, 0.5, 0.1; 206,78,51; 255,147,124; }
P { 0, "B"; 1.0, "B"; }
BrickMasonry { "P"; 0.05; 102,102,102; })";
    if (endsWith(".ashlar")) return "AshlarMasonry { 0.5,0.5,0.05; 1.5,0.5,0.1; 80,80,80; 100,100,90; 0.05; 9,9,9; }";
    if (endsWith(".cyclopean")) return "CyclopeanMasonry { stones, 20; 5; 90,90,80; 140,130,120; 0.03; 9,9,9; 0.02; }";
    return "Modifications { line, rel, 90, 0.3; line, rel, -90, 1.0; line, rel, -90, 0.3; }";
}

// The plan the structure's docks make, as a building is assembled from it (a few modules only).
void placeModules(const BuildingStructure &structure) {
    structureHash(structure);
    if (structure.modules.size() > 20) return;
    std::vector<FloorPlanModule> modules;
    for (const ModuleStructure &module : structure.modules) modules.push_back(module.module);
    std::vector<KkConnection> docks;
    for (const ModuleDock &d : structure.docks)
        docks.push_back({false, structure.moduleIndex(d.dominant, d.loc), d.edge,
                         structure.moduleIndex(d.docked, d.loc), d.dockedEdge, d.a, d.b, d.loc});
    FloorPlan plan(std::move(modules), std::move(docks), {});
}

// Every binding resolved, as the walls of its storeys and modules ask.
void resolveBindings(const BuildingStyle &style) {
    resolveStyle(style, "", 0);
    for (const auto &[storey, name] : style.bindings.storeys) resolveStyle(style, "", storey);
    for (const auto &[module, name] : style.bindings.modules) resolveStyle(style, module, 0);
}

void sweepRoundARectangle(const CorniceDescription &cornice) {
    ProfileOutline outline = traceProfile(cornice.profile, 10);
    if (outline.points.size() > 5000) return;
    double scale = heightScale(cornice.profile, outline, 0.5);
    ProfileOutline scaled = scaledOutline(outline, scale);
    SweepPath path{{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 10, true, OutwardSide::Right};
    sweepCornice(cornice, scaled, path, {});
    SweepPath run{{{0, 0}, {4, 0}}, 10, false, OutwardSide::Right};
    sweepCornice(cornice, scaled, run, {true, 2});
    for (const Console &console : cornice.consoles)
        if (console.spacing >= 0.05) placeConsoles(run, console, scaled, scale);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string text = fuzz::inputText(data, size);
    fuzz::expectInputError([&] { sweepRoundARectangle(parseCorniceDescription(text, "fuzz.cornice")); });
    fuzz::expectInputError([&] { layBond(parseBrickBond(text, "fuzz.bond")); });
    fuzz::expectInputError([&] { layStones(parseAshlarMasonry(text, "fuzz.ashlar")); });
    fuzz::expectInputError([&] { layCyclopean(parseCyclopeanMasonry(text, "fuzz.cyclopean")); });
    fuzz::expectInputError([&] {
        resolveBindings(parseBuildingStyle(
            text, "fuzz.style", [&](const std::string &name, const FileLoc &) { return namedFile(name, text); }));
    });
    fuzz::expectInputError([&] { placeModules(parseBuildingStructure(text, "fuzz.structure")); });
    return 0;
}
