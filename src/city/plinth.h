// The plinth of a building on terrain: a skirt of wall below the building's datum, so that
// where the ground under its walls lies lower than the datum no gap opens (docs/terrain.md,
// "Buildings on terrain").
#pragma once

#include "city/footprint.h"
#include "scene/mesh.h"

namespace veduta {

// The outer walls of `footprint` (counter-clockwise) from its base down by `depth` metres,
// facing out, with u along the outline and v down the wall in metres. Every triangle has
// material 0: the caller assigns one.
Mesh plinthMesh(const Footprint &footprint, float depth);

}  // namespace veduta
