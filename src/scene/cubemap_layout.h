// Conversions between a Cubemap and the images it comes from or is written as: six face
// images, a vertical or horizontal cross, and a lat-long (equirectangular) panorama.
// docs/cubemap.md shows the layouts.
#pragma once

#include <array>
#include <stdexcept>

#include "core/image.h"
#include "core/vecmath.h"
#include "scene/cubemap.h"

namespace veduta {

// An image that cannot be what it is given as. The message names the face or layout and the
// sizes; callers that know the file add its name.
class LayoutError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Blender's equirectangular mapping, so that an HDRI looks here as it does in Cycles: the
// image centre looks east (+x), u grows towards the south (−y), v from the top row:
// u = 0.5 − atan2(d.y, d.x) / 2π, v = 0.5 − asin(d.z) / π.
Vec3f latLongDirection(float u, float v);
Vec2f latLongPosition(const Vec3f &direction);

// Images need at least three channels (the first three are RGB, the rest are ignored) and
// faces must be square, of one size. Negative and NaN samples become 0 in the Cubemap.
Cubemap cubemapFromFaces(const std::array<Image, kCubeFaceCount> &faces);  // indexed by CubeFace
// A vertical (3:4) or horizontal (4:3) cross around the north face, told apart by its aspect.
Cubemap cubemapFromCross(const Image &cross);
// Each texel averages 4×4 bilinear lookups of the panorama.
Cubemap cubemapFromLatLong(const Image &latLong, int faceSize);

// Three-channel images. The cross is black outside its faces.
std::array<Image, kCubeFaceCount> facesFromCubemap(const Cubemap &cubemap);
Image crossFromCubemap(const Cubemap &cubemap, bool vertical);
// width × width/2 pixels, each the mean of 4×4 cubemap lookups.
Image latLongFromCubemap(const Cubemap &cubemap, int width);

}  // namespace veduta
