// The materials of a landscape's surfaces: one per land class (the terrain), one per pavement
// (the ribbons) and road paint. Each is the scene's material of that name when the scene
// defines one, so a scene can restyle any of them; otherwise the built-in one, which with a
// texture registry carries a procedural texture (geo/terrain_texture.h,
// geo/pavement_texture.h) and without one is the class's plain colour. docs/landscape.md.
#pragma once

#include <map>
#include <memory>
#include <utility>

#include "geo/atkis.h"
#include "geo/height_grid.h"
#include "geo/road_style.h"
#include "geo/shore_distance.h"
#include "geo/track_geometry.h"
#include "geodesy/local_frame.h"
#include "scene/render_scene.h"
#include "scene/textures.h"

namespace veduta {

class LandMaterials {
  public:
    // `addProcedural` may be empty: plain colours.
    // `shore` may be null: no water.
    LandMaterials(RenderSceneBuilder &builder, AddProcedural addProcedural, std::shared_ptr<const HeightGrid> grid,
                  LocalFrame frame, std::shared_ptr<const ShoreDistance> shore, uint32_t seed);

    MaterialId land(LandClass c);
    MaterialId pavement(Pavement pavement, int tracks);
    MaterialId marking();
    // `land/sleeper` (concrete) and `land/rail_steel` (rusty steel with a sheen on the head).
    MaterialId track(TrackSurface surface);

  private:
    RenderSceneBuilder &builder_;
    AddProcedural addProcedural_;
    std::shared_ptr<const HeightGrid> grid_;
    LocalFrame frame_;
    std::shared_ptr<const ShoreDistance> shore_;
    uint32_t seed_;
    std::map<LandClass, MaterialId> land_;
    std::map<std::pair<Pavement, int>, MaterialId> pavements_;
};

// The terrain's and the ribbons' texture coordinates are in tiles of this many metres
// (terrain_mesh.h, RibbonOptions::tileLength); a textured land material reads them in metres.
inline constexpr float kLandTileMetres = 10;

}  // namespace veduta
