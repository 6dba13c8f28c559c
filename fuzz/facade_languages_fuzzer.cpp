// Finkenzeller's small languages (docs/facades.md) on any text: the text read as a cornice
// description, a brick bond and an ashlar description. What reads is then used as a facade uses
// it, on a small wall with a window and round a small rectangle, skipping only what would be too
// fine to finish quickly (the readers' own limits allow a million bricks, which is correct but
// slow per input). Bad input must be an InputError, whichever step finds it.
#include <string>
#include <vector>

#include "facade/ashlar.h"
#include "facade/brick_bond.h"
#include "facade/consoles.h"
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
    return 0;
}
