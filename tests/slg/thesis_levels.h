// The plan parameters of the thesis's levels (digest-003 §4.3, Tables 9, 13 and 16) as the
// SLG tests use them, written out so that a test reads what it plans with.
#pragma once

#include "slg/plan_parameters.h"

namespace veduta {

inline PlanParameters apartmentLevel() {  // Table 16
    PlanParameters p;
    p.rule = LandmarkRule::Growth;
    p.averageArea = 10;
    p.sideRatio = 1.0 / 3;
    p.scale = 1;
    p.exponent = 3;
    p.minimumCount = 3;
    p.jitter = 0.05;
    p.reflexLimits = {1, 1, 0};
    return p;
}

inline PlanParameters storeyLevel() {  // Table 13
    PlanParameters p;
    p.rule = LandmarkRule::Growth;
    p.averageArea = 30;
    p.sideRatio = 0.5;
    p.scale = 15;
    p.exponent = 2;
    p.jitter = 0.05;
    p.reflexLimits = {1, 1, 0};
    return p;
}

inline PlanParameters blockLevel(double lotArea) {  // Table 9
    PlanParameters p;
    p.rule = LandmarkRule::Perimeter;
    p.averageArea = lotArea;
    p.sideRatio = 0.5;
    p.jitter = 0.05;
    return p;
}

}  // namespace veduta
