// An endless ground: a horizontal plane at one height out to 10,000 km, so that no band of
// sky shows below the horizon where the scene's own ground ends. Its texture coordinates are
// metres, as a <plane>'s; to keep them precise near the scene it is made of square rings,
// each ten times the last, around a square of 2 km.
#pragma once

#include "scene/mesh.h"

namespace veduta {

Mesh makeGround(float height);

}  // namespace veduta
