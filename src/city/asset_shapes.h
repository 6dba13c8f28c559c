// The built-in assets (assets.h) by family, each in its own file.
#pragma once

#include <vector>

#include "city/assets.h"

namespace veduta {

std::vector<Asset> wallAssets();      // asset_walls.cpp: Wall0, Wall+1, WallHole, Glass0, Glass+1
std::vector<Asset> openingAssets();   // asset_openings.cpp: windows and entrances
std::vector<Asset> mouldingAssets();  // asset_mouldings.cpp: cornices, window pediments, the column
std::vector<Asset> balconyAssets();   // asset_balconies.cpp: balconies, their roofs and doors
std::vector<Asset> gutterAssets();    // asset_gutters.cpp: gutter, its end, the cylinder of pipes and bars

}  // namespace veduta
