// Finkenzeller's buildings in a scene (<modular_building>, docs/facades.md): the structure and
// style files read, the building assembled (facade/facade_building.h), its masonry baked into one
// texture atlas at the texel size the camera asks for, written beside the texture cache through
// the image library and given back to the walls as maps, and its consoles set as instances of
// their model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "city/citygml_buildings.h"
#include "description/scene_description.h"
#include "scene/camera.h"
#include "scene/render_scene.h"

namespace veduta {

// The most texels one building's masonry atlas may have; finer asks are coarsened
// (facade/masonry_atlas.h), so that a building costs at most 32 bytes a texel while it is baked
// (64 MB). Past a million texels the texture registry reads an atlas tile by tile as the renderer
// asks, rather than whole: a building close to the camera then costs only what it shows.
inline constexpr size_t kModularBuildingTexels = size_t(1) << 21;
// The finest texel asked for, metres: finer than a brick's chamfer shows nothing more.
inline constexpr double kFinestMasonryTexel = 0.002;

// Adds the building: its mesh as a world mesh with the element's object and building ids, a
// building record, its consoles as instances. The building's notes (openings left out and why)
// are appended to `warnings` at the element's place. Throws InputError at the files' places.
void generateModularBuilding(const ModularBuildingDesc &desc, uint32_t seed, const Camera &camera,
                             RenderSceneBuilder &builder, const AddTexture &addTexture,
                             std::vector<std::string> &warnings);

}  // namespace veduta
