// Bilke's CreateBuildingStartShapes (Bilke 2009, §2.4, thesis L1275): one facade start shape
// per footprint edge, named for the grammar by where the edge lies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "city/footprint.h"
#include "core/vecmath.h"

namespace veduta {

struct StartShape {
    std::string symbol;  // FrontFacade, Facade, BackFacade, SideFacade or SmallFacade
    uint32_t edge = 0;   // the footprint edge it stands on
    float width = 0, height = 0;
    // Facade frame (right, up, out) → world; origin at the edge's left end (seen from outside)
    // at the base.
    Transform facadeToWorld;
};

struct StartShapeSettings {
    float smallFacadeWidth = 3;  // the thesis' 3 m
    // A non-street edge whose outward normal makes at most this cosine with the front's faces
    // the courtyard: the default, −0.5, takes edges turned more than 120° from the front.
    float backFacadeCosine = -0.5f;
};

// One start shape per edge of a normalised footprint, in edge order. The labels, in order of
// precedence (docs/roofs.md):
//   FrontFacade  the longest street edge; the longest edge when none faces a street
//   Facade       every other street edge, whatever its width
//   SmallFacade  any other edge shorter than smallFacadeWidth
//   BackFacade   any other edge facing away from the front (the courtyard side)
//   SideFacade   the rest
// Ties in length go to the lowest edge index.
std::vector<StartShape> makeStartShapes(const Footprint &footprint, float wallHeight,
                                        const StartShapeSettings &settings = {});

}  // namespace veduta
