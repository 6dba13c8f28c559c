// Streets traced through a tensor field (Chen et al. 2008, §5): streamlines of the major
// directions become main streets and those of the minor directions side streets, each family
// kept `separation` apart, every streamline seeded from those already traced so that the two
// families cross; the streamlines are then drawn into a street graph under the same local
// constraints as the L-system's streets (street_constraints.h) and stopped by the same ground
// (StreetEnvironment). docs/tensor-streets.md.
#pragma once

#include <cstddef>
#include <vector>

#include "core/vecmath.h"
#include "streets/street_builder.h"
#include "streets/street_constraints.h"
#include "streets/street_graph.h"
#include "streets/street_growth.h"
#include "streets/tensor_field.h"

namespace veduta {

struct StreamlineSettings {
    float majorSeparation = 160;   // between main streets of one direction
    float minorSeparation = 80;    // between side streets
    float step = 4;                // of the integration (Runge–Kutta, second order)
    float segment = 24;            // the length of the streets a streamline is drawn as
    size_t maxStreamlines = 4000;  // a limit, checked: a warning says when it was reached
};

// A traced streamline: its points, every `step` metres, and whether it is of the main family.
struct Streamline {
    std::vector<Vec2f> points;
    bool major = true;
};

struct TracedStreets {
    std::vector<Streamline> streamlines;  // in the order they were traced
    StreetGraph graph;
    StreetCounts counts;        // of the segments drawn, as the L-system's builder counts its F words
    bool limitReached = false;  // maxStreamlines stopped the tracing
};

// The streamlines of `field` inside `window` and the streets drawn along them; with an
// environment, no streamline crosses ground the streets may not cross. Deterministic: the seeds
// are taken in the order they were found.
TracedStreets traceStreets(const TensorField &field, const GrowthWindow &window, const StreamlineSettings &settings,
                           const StreetConstraints &constraints = {}, const StreetEnvironment *environment = nullptr);

}  // namespace veduta
