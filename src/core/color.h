// Colour helpers for linear Rec.709 RGB, the space veduta renders in.
#pragma once

#include "core/vecmath.h"

namespace veduta {

// Relative luminance Y of linear Rec.709 RGB (ITU-R BT.709 weights).
inline float luminance(const Vec3f &rgb) { return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z; }

}  // namespace veduta
