// The plinth of a building on terrain: a skirt of wall below the building's datum, so that
// where the ground under its walls lies lower than the datum no gap opens (docs/terrain.md,
// "Buildings on terrain").
#pragma once

#include "city/building_generator.h"
#include "city/footprint.h"
#include "scene/mesh.h"
#include "scene/render_scene.h"

namespace veduta {

// How far a building's plinth reaches below its datum on terrain.
inline constexpr float kPlinthDepth = 0.5f;

// The outer walls of `footprint` (counter-clockwise) from its base down by `depth` metres,
// facing out, with u along the outline and v down the wall in metres. Every triangle has
// material 0: the caller assigns one.
Mesh plinthMesh(const Footprint &footprint, float depth);

// The material "plinth", added to the scene when first asked for.
MaterialId plinthMaterial(RenderSceneBuilder &builder);

// The plinth of a building on terrain, kPlinthDepth deep, in the
// material "plinth", with the building's ids.
void addPlinth(const BuildingSpec &spec, RenderSceneBuilder &builder);

}  // namespace veduta
