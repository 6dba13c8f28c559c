// How far a point of the terrain lies from the nearest shore: the outlines of a landscape's lakes,
// ponds and rivers, kept in a grid of cells so that a texture lookup reads only the few edges
// near it. The ground's texture turns to wet silt along them (geo/terrain_texture.h).
#pragma once

#include <unordered_map>
#include <utility>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

class ShoreDistance {
  public:
    // The shore's edges in local metres.
    explicit ShoreDistance(const std::vector<std::pair<Vec2d, Vec2d>> &edges);

    // The distance from p to the nearest edge, or `reach` when none lies within it.
    double distance(Vec2d p, double reach) const;

  private:
    static constexpr double kCell = 16;  // metres
    std::vector<std::pair<Vec2d, Vec2d>> edges_;
    std::unordered_map<int64_t, std::vector<uint32_t>> cells_;  // cell → edges that reach it
};

}  // namespace veduta
