// The cornices that rule files ask for with <Cornice> (city/rules.h): the places where the
// grammar set the named model on a building's facades, joined into runs and swept with the
// cornice file's profile (facade/cornice_run.h), so that a main cornice runs unbroken along the
// facade and round the corners, mitred, instead of as a row of model pieces meeting at butt
// joints.
//
// Choices where the rule file leaves it open:
// * One run is made of places of one <Cornice>, in one material, at one height: their bottoms and
//   tops agree within kCorniceJoinTolerance. Places on one facade that overlap or touch within
//   that tolerance are one stretch.
// * A stretch that reaches a facade's right end continues on the facade that begins at that
//   corner when a stretch there begins at its left end, unless the corner turns more than the
//   sweep allows (kSweepTurnLimit); there the runs end. Stretches that go all the way round are
//   one closed ring.
// * The profile fills the places' height, its lowest point on their bottom (Def 5.9); its depth
//   follows from the profile, not from the model's. Open ends are capped.
#pragma once

#include <vector>

#include "city/rules.h"
#include "city/start_shapes.h"
#include "facade/cornice_run.h"
#include "scene/mesh.h"

namespace veduta {

// Metres within which the places' heights and ends count as the same.
inline constexpr double kCorniceJoinTolerance = 1e-3;

// Where the grammar set a <Cornice>'s model: facade metres of the start shape `facade` (an
// index into the building's start shapes).
struct CornicePlace {
    const CorniceRule *rule = nullptr;
    size_t facade = 0;
    double left = 0, right = 0, bottom = 0, top = 0;
    MaterialId material = kNoMaterial;
};

// The runs swept into one mesh (world metres), and their consoles, whose files are given as
// paths beside their cornice file.
CorniceRun sweepRuleCornices(const std::vector<CornicePlace> &places, const std::vector<StartShape> &facades);

}  // namespace veduta
