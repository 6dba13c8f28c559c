// What the terrain tells the buildings: the height a footprint stands on. The landscape makes
// it (src/geo), the building generators ask it (src/city); it lives here, below both.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

// The height a footprint stands on when its building gives none: the landscape's lowest
// terrain point under it (docs/landscape.md); nullopt where the footprint misses the terrain.
// An empty function: flat ground at 0.
using GroundHeight = std::function<std::optional<float>(const std::vector<Vec2f> &footprint)>;

}  // namespace veduta
