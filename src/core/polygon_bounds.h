// The bounding rectangle of plane points: what the facade code (aprons under their windows) and
// the masonry bake (a tile's stones and openings) both take of an outline.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

// The lower left and upper right corners; the points must not be empty.
inline std::pair<Vec2d, Vec2d> polygonBounds(const std::vector<Vec2d> &points) {
    Vec2d low = points.front(), high = points.front();
    for (Vec2d p : points) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    return {low, high};
}

}  // namespace veduta
