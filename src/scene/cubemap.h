// A cubemap: six square faces of linear RGB radiance around the scene, in the ENU frame
// (x east, y north, z up). docs/cubemap.md shows how each face is oriented.
//
// Each face is stored as seen from the cube's centre looking out through it, the top image
// row first. Side faces have the sky at the top; the up face has south at the top, the down
// face north, and both have east on the right, so that the faces join without seams in the
// usual vertical and horizontal crosses around the north face.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "core/vecmath.h"

namespace veduta {

enum CubeFace : int { kEast = 0, kWest, kNorth, kSouth, kUp, kDown };  // +x, −x, +y, −y, +z, −z
inline constexpr int kCubeFaceCount = 6;

// The directions a face image spans: a texel at face coordinates (a, b) ∈ [−1, 1]² looks
// along forward + a·right + b·up, where a grows to the right and b upwards in the image.
struct CubeFaceFrame {
    Vec3f forward, right, up;
};
const CubeFaceFrame &cubeFaceFrame(int face);
std::string_view cubeFaceName(int face);  // "east", "west", "north", "south", "up", "down"

// Where a direction meets the cube: the face and the continuous texel position on it,
// x ∈ [0, size) from the left, y ∈ [0, size) from the top.
struct CubeTexel {
    int face = 0;
    float x = 0, y = 0;
};

// The geometry of a cube of size×size texels per face, which needs no texels: the sampling
// distribution shares it without holding the radiance. The Cubemap members below call these.
inline float cubeFaceCoordinate(float position, int size) { return 2 * position / float(size) - 1; }
Vec3f cubeDirection(int size, int face, float x, float y);
CubeTexel cubeLocate(int size, const Vec3f &direction);
double cubeTexelSolidAngle(int size, int x, int y);

class Cubemap {
  public:
    Cubemap() = default;
    explicit Cubemap(int size);  // all black

    int size() const { return size_; }
    bool empty() const { return size_ == 0; }

    Vec3f &texel(int face, int x, int y) { return faces_[face][size_t(y) * size_t(size_) + size_t(x)]; }
    const Vec3f &texel(int face, int x, int y) const { return faces_[face][size_t(y) * size_t(size_) + size_t(x)]; }

    // The unit direction through continuous texel position (x, y) of a face.
    Vec3f direction(int face, float x, float y) const;
    CubeTexel locate(const Vec3f &direction) const;
    // Radiance towards a direction, bilinear between texel centres and continuous across
    // the edges and corners where faces meet.
    Vec3f lookup(const Vec3f &direction) const;
    // The solid angle a texel subtends.
    float texelSolidAngle(int x, int y) const;
    // A texel, or for x or y one beyond a face's edge (−1 or size) the texel of the
    // neighbouring face that adjoins across that edge; one beyond a corner, the mean of the
    // three texels that meet at the cube's corner. The lookup's bilinear taps come from here.
    Vec3f texelAcrossEdges(int face, int x, int y) const;

  private:
    int size_ = 0;
    std::array<std::vector<Vec3f>, kCubeFaceCount> faces_;
};

}  // namespace veduta
