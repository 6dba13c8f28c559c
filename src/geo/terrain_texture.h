// The ground of a land class (geo/atkis.h) computed where it is looked up, from a metre to
// kilometres away: the class's colour varied at four scales (fields and meadows in patches of
// a few hundred metres, tussocks and clods of metres, a fine mottle) with the class's own
// pattern (furrows on farmland, litter on the forest floor), turning to scree and rock where the
// DGM is steep, to alpine ground above the tree line and to wet silt along the shores of lakes
// and rivers (seed 004's terrain remainders). (u, v)
// are local metres of the scene (a material reads the terrain's tile units with textureSize
// 1 / tile), so the texture knows where it is on the DGM. Pattern finer than the footprint
// gives way to its mean. docs/landscape.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "geo/atkis.h"
#include "geo/height_grid.h"
#include "geo/shore_distance.h"
#include "geodesy/local_frame.h"
#include "scene/textures.h"

namespace veduta {

struct TerrainLook {
    double screeSlope = 38, rockSlope = 45, bareRockSlope = 55;  // degrees
    double treeLine = 1800;                                      // metres above sea level
    double snowLine = 2600;
    double shoreWidth = 2.5;  // metres of wet silt along the water
};

class TerrainTexture : public ProceduralTexture {
  public:
    // `shore` may be null: no water.
    TerrainTexture(LandClass landClass, Vec3f albedo, std::shared_ptr<const HeightGrid> grid, LocalFrame frame,
                   std::shared_ptr<const ShoreDistance> shore, uint32_t seed, TerrainLook look = {});

    int channels() const override { return 3; }
    std::string fingerprint() const override;
    void lookup(Vec2f uv, float footprint, float *out, int count) const override;

  private:
    Vec3f ground(Vec2d p, double footprint) const;

    LandClass landClass_;
    Vec3f albedo_;
    std::shared_ptr<const HeightGrid> grid_;
    LocalFrame frame_;
    std::shared_ptr<const ShoreDistance> shore_;
    uint32_t seed_;
    TerrainLook look_;
};

// Whether a tree may grow where the terrain is as steep or as high as at `p` (local metres):
// not on rock, not above the tree line.
bool treeMayGrow(const HeightGrid &grid, const LocalFrame &frame, Vec2d p, const TerrainLook &look = {});

}  // namespace veduta
