#include "scene/cubemap_layout.h"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

namespace veduta {

namespace {

// Supersampling per texel or pixel, each way, in the lat-long conversions.
constexpr int kSupersampling = 4;

// Where a face sits in a cross, in face-sized tiles; a rotated face is turned by 180°.
struct CrossTile {
    int face, column, row;
    bool rotated;
};

constexpr std::array<CrossTile, kCubeFaceCount> kVerticalCross{{
    {kUp, 1, 0, false},
    {kWest, 0, 1, false},
    {kNorth, 1, 1, false},
    {kEast, 2, 1, false},
    {kDown, 1, 2, false},
    {kSouth, 1, 3, true},
}};
constexpr std::array<CrossTile, kCubeFaceCount> kHorizontalCross{{
    {kUp, 1, 0, false},
    {kWest, 0, 1, false},
    {kNorth, 1, 1, false},
    {kEast, 2, 1, false},
    {kSouth, 3, 1, false},
    {kDown, 1, 2, false},
}};

// Calls copy(face x, face y, cross x, cross y) for every texel of every face of a cross.
template <typename Copy>
void forEachCrossPixel(const std::array<CrossTile, kCubeFaceCount> &tiles, int size, Copy copy) {
    for (const CrossTile &tile : tiles) {
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                int tx = tile.rotated ? size - 1 - x : x, ty = tile.rotated ? size - 1 - y : y;
                copy(tile.face, x, y, tile.column * size + tx, tile.row * size + ty);
            }
        }
    }
}

std::string faceLabel(int face) { return fmt::format("face '{}'", cubeFaceName(face)); }

void checkImage(const Image &image, const std::string &what) {
    if (image.width <= 0 || image.height <= 0) {
        throw LayoutError(fmt::format("{} is empty ({}x{})", what, image.width, image.height));
    }
    if (image.channels < 3) {
        throw LayoutError(fmt::format("{} has {} channel{}, at least 3 (RGB) are needed", what, image.channels,
                                      image.channels == 1 ? "" : "s"));
    }
}

// Negative and NaN samples become 0: DWAB-compressed EXRs carry tiny negative values, and
// the sampling distribution and its estimators take radiance as non-negative.
float radiance(float sample) { return sample > 0 ? sample : 0.0f; }

Vec3f rgb(const Image &image, int x, int y) {
    const float *p = image.at(x, y);
    return {radiance(p[0]), radiance(p[1]), radiance(p[2])};
}

void setRgb(Image &image, int x, int y, const Vec3f &value) {
    float *p = image.at(x, y);
    p[0] = value.x;
    p[1] = value.y;
    p[2] = value.z;
}

// A lat-long pixel by index, continued past the image's edges as the sphere continues:
// across the ±180° seam to the other side, and past a pole to the same row half-way round.
Vec3f latLongPixel(const Image &image, int x, int y) {
    if (y < 0 || y >= image.height) {
        y = y < 0 ? -1 - y : 2 * image.height - 1 - y;
        x += image.width / 2;
    }
    x %= image.width;
    if (x < 0) x += image.width;
    return rgb(image, x, y);
}

Vec3f bilinearLatLong(const Image &image, Vec2f uv) {
    float px = uv.x * float(image.width) - 0.5f, py = uv.y * float(image.height) - 0.5f;
    int x0 = int(std::floor(px)), y0 = int(std::floor(py));
    float fx = px - float(x0), fy = py - float(y0);
    return (latLongPixel(image, x0, y0) * (1 - fx) + latLongPixel(image, x0 + 1, y0) * fx) * (1 - fy) +
        (latLongPixel(image, x0, y0 + 1) * (1 - fx) + latLongPixel(image, x0 + 1, y0 + 1) * fx) * fy;
}

// The mean of f at kSupersampling² stratum centres of the unit square around (x, y).
template <typename F>
Vec3f supersampled(float x, float y, F f) {
    Vec3f sum(0.0f);
    for (int j = 0; j < kSupersampling; ++j) {
        for (int i = 0; i < kSupersampling; ++i) {
            sum += f(x + (float(i) + 0.5f) / kSupersampling, y + (float(j) + 0.5f) / kSupersampling);
        }
    }
    return sum / float(kSupersampling * kSupersampling);
}

}  // namespace

Vec3f latLongDirection(float u, float v) {
    float phi = (0.5f - u) * 2 * kPi, latitude = (0.5f - v) * kPi;
    float c = std::cos(latitude);
    return {c * std::cos(phi), c * std::sin(phi), std::sin(latitude)};
}

Vec2f latLongPosition(const Vec3f &d) {
    float z = std::clamp(d.z / length(d), -1.0f, 1.0f);
    return {0.5f - std::atan2(d.y, d.x) / (2 * kPi), 0.5f - std::asin(z) / kPi};
}

Cubemap cubemapFromFaces(const std::array<Image, kCubeFaceCount> &faces) {
    const Image &first = faces[0];
    for (int f = 0; f < kCubeFaceCount; ++f) {
        const Image &face = faces[size_t(f)];
        checkImage(face, faceLabel(f));
        if (face.width != face.height) {
            throw LayoutError(fmt::format("{} is {}x{}, faces must be square", faceLabel(f), face.width, face.height));
        }
        if (face.width != first.width) {
            throw LayoutError(fmt::format("{} is {}x{} but {} is {}x{}, all faces must be the same size", faceLabel(f),
                                          face.width, face.height, faceLabel(0), first.width, first.height));
        }
    }
    Cubemap cube(faces[0].width);
    for (int f = 0; f < kCubeFaceCount; ++f) {
        for (int y = 0; y < cube.size(); ++y) {
            for (int x = 0; x < cube.size(); ++x) cube.texel(f, x, y) = rgb(faces[size_t(f)], x, y);
        }
    }
    return cube;
}

Cubemap cubemapFromCross(const Image &cross) {
    checkImage(cross, "cross image");
    bool vertical = cross.width % 3 == 0 && cross.height == cross.width / 3 * 4;
    bool horizontal = cross.width % 4 == 0 && cross.height == cross.width / 4 * 3;
    if (!vertical && !horizontal) {
        throw LayoutError(
            fmt::format("cross image is {}x{}; a cross is 3:4 (vertical) or 4:3 (horizontal) with "
                        "square faces of whole pixels",
                        cross.width, cross.height));
    }
    Cubemap cube(vertical ? cross.width / 3 : cross.width / 4);
    forEachCrossPixel(vertical ? kVerticalCross : kHorizontalCross, cube.size(),
                      [&](int face, int x, int y, int cx, int cy) { cube.texel(face, x, y) = rgb(cross, cx, cy); });
    return cube;
}

Cubemap cubemapFromLatLong(const Image &latLong, int faceSize) {
    checkImage(latLong, "lat-long image");
    if (latLong.width != 2 * latLong.height) {
        throw LayoutError(
            fmt::format("lat-long image is {}x{}, it must be twice as wide as high", latLong.width, latLong.height));
    }
    if (faceSize <= 0) throw LayoutError(fmt::format("cube face size is {}, it must be positive", faceSize));
    Cubemap cube(faceSize);
    tbb::parallel_for(0, kCubeFaceCount * faceSize, [&](int row) {
        int face = row / faceSize, y = row % faceSize;
        for (int x = 0; x < faceSize; ++x) {
            cube.texel(face, x, y) = supersampled(float(x), float(y), [&](float sx, float sy) {
                return bilinearLatLong(latLong, latLongPosition(cube.direction(face, sx, sy)));
            });
        }
    });
    return cube;
}

std::array<Image, kCubeFaceCount> facesFromCubemap(const Cubemap &cubemap) {
    std::array<Image, kCubeFaceCount> faces;
    for (int f = 0; f < kCubeFaceCount; ++f) {
        Image &face = faces[size_t(f)];
        face = Image(cubemap.size(), cubemap.size(), 3);
        for (int y = 0; y < cubemap.size(); ++y) {
            for (int x = 0; x < cubemap.size(); ++x) setRgb(face, x, y, cubemap.texel(f, x, y));
        }
    }
    return faces;
}

Image crossFromCubemap(const Cubemap &cubemap, bool vertical) {
    int n = cubemap.size();
    Image cross(vertical ? 3 * n : 4 * n, vertical ? 4 * n : 3 * n, 3);
    forEachCrossPixel(vertical ? kVerticalCross : kHorizontalCross, n, [&](int face, int x, int y, int cx, int cy) {
        setRgb(cross, cx, cy, cubemap.texel(face, x, y));
    });
    return cross;
}

Image latLongFromCubemap(const Cubemap &cubemap, int width) {
    if (cubemap.empty()) throw LayoutError("the cubemap is empty");
    if (width <= 0 || width % 2 != 0) {
        throw LayoutError(fmt::format("lat-long width is {}, it must be positive and even", width));
    }
    Image latLong(width, width / 2, 3);
    tbb::parallel_for(0, latLong.height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            setRgb(latLong, x, y, supersampled(float(x), float(y), [&](float sx, float sy) {
                       return cubemap.lookup(latLongDirection(sx / float(width), sy / float(latLong.height)));
                   }));
        }
    });
    return latLong;
}

}  // namespace veduta
