// T14 (Bilke 2009 (digest §10)): a labelled cubemap, each face one colour, must show the right label
// in each ENU direction, whether it is built face by face, read from a vertical or horizontal
// cross drawn as docs/cubemap.md shows them, or assembled from Bilke's CubeMapGen images.
#include <gtest/gtest.h>

#include <array>
#include <string_view>

#include "scene/cubemap.h"
#include "scene/cubemap_layout.h"

namespace veduta {
namespace {

constexpr int kSize = 4;

// One colour per face, indexed by CubeFace.
const std::array<Vec3f, kCubeFaceCount> kLabels{{
    {1, 0, 0},  // east
    {0, 1, 0},  // west
    {0, 0, 1},  // north
    {1, 1, 0},  // south
    {0, 1, 1},  // up
    {1, 0, 1},  // down
}};

struct Compass {
    std::string_view name;
    Vec3f direction;
    CubeFace face;
};
const std::array<Compass, kCubeFaceCount> kCompass{{
    {"east", {1, 0, 0}, kEast},
    {"west", {-1, 0, 0}, kWest},
    {"north", {0, 1, 0}, kNorth},
    {"south", {0, -1, 0}, kSouth},
    {"up", {0, 0, 1}, kUp},
    {"down", {0, 0, -1}, kDown},
}};

Image labelImage(const Vec3f &label) {
    Image image(kSize, kSize, 3);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            image.at(x, y)[0] = label.x;
            image.at(x, y)[1] = label.y;
            image.at(x, y)[2] = label.z;
        }
    }
    return image;
}

// Paints a face's label into the square at (column, row) of a cross, in face units.
void paintSquare(Image &cross, int column, int row, const Vec3f &label) {
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            float *pixel = cross.at(column * kSize + x, row * kSize + y);
            pixel[0] = label.x;
            pixel[1] = label.y;
            pixel[2] = label.z;
        }
    }
}

// Looks along each compass direction and a little off it (still well inside the face), so
// that a face that is only right at its centre would show.
void expectLabelsInEveryDirection(const Cubemap &cube) {
    for (const Compass &c : kCompass) {
        const CubeFaceFrame &frame = cubeFaceFrame(c.face);
        for (Vec3f offset :
             {Vec3f(0.0f), 0.3f * frame.right + 0.2f * frame.up, -0.3f * frame.right - 0.2f * frame.up}) {
            EXPECT_EQ(cube.lookup(normalize(c.direction + offset)), kLabels[c.face]) << c.name;
        }
    }
}

TEST(CubemapEnu, FacesLookAlongTheirCompassDirections) {
    for (const Compass &c : kCompass) {
        EXPECT_EQ(cubeFaceName(c.face), c.name);
        EXPECT_EQ(cubeFaceFrame(c.face).forward, c.direction) << c.name;
    }
}

TEST(CubemapEnu, LabelledFacesAreSeenInTheirDirections) {
    std::array<Image, kCubeFaceCount> faces;
    for (int face = 0; face < kCubeFaceCount; ++face) faces[face] = labelImage(kLabels[face]);
    expectLabelsInEveryDirection(cubemapFromFaces(faces));
}

// The vertical cross of docs/cubemap.md: up on top, then west, north, east, then down, then
// south (rotated, which a constant label does not show).
TEST(CubemapEnu, VerticalCrossPlacesFacesAsDocumented) {
    Image cross(3 * kSize, 4 * kSize, 3);
    paintSquare(cross, 1, 0, kLabels[kUp]);
    paintSquare(cross, 0, 1, kLabels[kWest]);
    paintSquare(cross, 1, 1, kLabels[kNorth]);
    paintSquare(cross, 2, 1, kLabels[kEast]);
    paintSquare(cross, 1, 2, kLabels[kDown]);
    paintSquare(cross, 1, 3, kLabels[kSouth]);
    expectLabelsInEveryDirection(cubemapFromCross(cross));
}

TEST(CubemapEnu, HorizontalCrossPlacesFacesAsDocumented) {
    Image cross(4 * kSize, 3 * kSize, 3);
    paintSquare(cross, 1, 0, kLabels[kUp]);
    paintSquare(cross, 0, 1, kLabels[kWest]);
    paintSquare(cross, 1, 1, kLabels[kNorth]);
    paintSquare(cross, 2, 1, kLabels[kEast]);
    paintSquare(cross, 3, 1, kLabels[kSouth]);
    paintSquare(cross, 1, 2, kLabels[kDown]);
    expectLabelsInEveryDirection(cubemapFromCross(cross));
}

// Bilke 2009 split its Vue crosses with ATI CubeMapGen into c00…c05 = east, west, north, south,
// down, up (Bilke 2009, §2.3, docs/cubemap.md). veduta names no such files, so the mapping is
// this table: images in CubeMapGen's order, placed by it, show their labels towards ENU.
TEST(CubemapEnu, CubeMapGenOrderMapsToEnuFaces) {
    struct CubeMapGenImage {
        std::string_view file;
        CubeFace face;
        Vec3f direction;
    };
    const std::array<CubeMapGenImage, kCubeFaceCount> order{{
        {"c00", kEast, {1, 0, 0}},
        {"c01", kWest, {-1, 0, 0}},
        {"c02", kNorth, {0, 1, 0}},
        {"c03", kSouth, {0, -1, 0}},
        {"c04", kDown, {0, 0, -1}},
        {"c05", kUp, {0, 0, 1}},
    }};
    // Each image labelled by its position in CubeMapGen's order.
    std::array<Vec3f, kCubeFaceCount> labelOfImage{};
    std::array<Image, kCubeFaceCount> faces;
    for (size_t i = 0; i < order.size(); ++i) {
        labelOfImage[i] = {float(i + 1), 0.5f, 0.25f};
        faces[order[i].face] = labelImage(labelOfImage[i]);
    }
    Cubemap cube = cubemapFromFaces(faces);
    for (size_t i = 0; i < order.size(); ++i) {
        EXPECT_EQ(cube.lookup(order[i].direction), labelOfImage[i]) << order[i].file;
    }
}

}  // namespace
}  // namespace veduta
