// One cornice description made into geometry along one run of an outline (digest-001 §2.6): the
// profile scaled so that its height fills the band it stands on (L1128), swept with mitred
// corners (profile_sweep.h), and its consoles set along it (consoles.h). Modular buildings sweep
// their bands with it, and the grammar's buildings the models their rule files' <Cornice> names.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "core/vecmath.h"
#include "facade/profile.h"
#include "facade/profile_sweep.h"
#include "scene/mesh.h"

namespace veduta {

// A console model set along a cornice: one instance per transform (consoles.h's unit box).
struct ConsoleSet {
    std::string objectFile;  // as the cornice description names it
    FileLoc loc;
    MaterialId material = kNoMaterial;
    std::vector<Transform> transforms;
};

struct CorniceRun {
    Mesh mesh;                         // world metres, every triangle in the run's material
    std::vector<ConsoleSet> consoles;  // one per console of the description that found room
};

// The run through `points` (plan metres) with neighbours closer than a micrometre made one and,
// closed, its repeated first point dropped, keeping only the points where it turns: joints along
// one straight wall are no corners for the sweep. Fewer than 2 points (3 closed) remain where the
// run has no length.
SweepPath sweepPathThrough(const std::vector<Vec2d> &points, double baseHeight, bool closed, OutwardSide outward);

// `cornice` swept along `path` (open runs capped at their ends), its profile filling `bandHeight`
// metres up from the path's base, in `material`. InputError at the profile or a console as
// traceProfile, heightScale and placeConsoles throw it.
CorniceRun buildCorniceRun(const CorniceDescription &cornice, const SweepPath &path, double bandHeight,
                           MaterialId material);

}  // namespace veduta
