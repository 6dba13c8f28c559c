// Up-axis conversions. veduta's scene frame is Z up (DESIGN.md: X east, Y north, Z up); seed
// 000 builds its models Y up and turns them with TransformGeoZUp (Bilke 2009, §2.4), and glTF
// files are Y up. Both conversions are rotations about X, so they keep handedness, winding and
// lengths, and normals turn with the same matrix as positions.
#pragma once

#include "core/vecmath.h"

namespace veduta {

// Bilke's TransformGeoZUp: rows (1,0,0), (0,0,−1), (0,1,0).
inline constexpr Transform kYUpToZUp{{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0}};
// Its inverse (and transpose), Z up to Y up.
inline constexpr Transform kZUpToYUp{{1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0}};

// (x, y, z) → (x, −z, y)
inline Vec3f yUpToZUp(const Vec3f &v) { return {v.x, -v.z, v.y}; }
// (x, y, z) → (x, z, −y)
inline Vec3f zUpToYUp(const Vec3f &v) { return {v.x, v.z, -v.y}; }

}  // namespace veduta
