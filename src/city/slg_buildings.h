// The <slg> element (docs/slg.md): a block or a district planned with Schrader's Spatial
// Landmark Graph from the urban-geography tables alone — the district cut into blocks between
// streets, each block into lots, each lot's building planned down to its rooms and built at the
// level of detail its size in the image and its distance from the camera ask for — with its
// streets, block surfaces and sidewalks.
#pragma once

#include <string>
#include <vector>

#include "city/atkis_slg_input.h"
#include "description/scene_description.h"
#include "geo/ground_height.h"
#include "scene/render_scene.h"

namespace veduta {

// What <slg level="atkis"> builds on: the landscape's settlement areas and building
// footprints, and its ground.
struct SlgLand {
    SlgLandInput input;
    GroundHeight ground;
};

// Every <slg> of a scene at once, each with its seed: the geometry budget
// (RenderSceneBuilder::setGeometryBudget) goes to the buildings nearest the camera whichever
// element they are in. `land` is null in a scene without a <landscape>.
void generateSlg(const std::vector<SlgDesc> &descs, const std::vector<uint32_t> &seeds, const Camera &camera,
                 const SlgLand *land, RenderSceneBuilder &builder, std::vector<std::string> &warnings);

}  // namespace veduta
